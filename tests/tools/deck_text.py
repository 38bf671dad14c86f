"""A minimal reader of the decks the generators write, for the invariants the tests check: the nodes, the elements
(type and node labels, continuation lines joined) and the node sets (labels, GENERATE expanded)."""


def read_deck(text):
    """(nodes {label: coordinates}, elements [(type, label, [node labels])], nsets {name: [labels]})."""
    nodes, elements, nsets = {}, [], {}
    block, etype, nset, generate = None, None, None, False
    pending = None
    for raw in text.splitlines():
        line = raw.strip()
        if not line or line.startswith('**'):
            continue
        if line.startswith('*'):
            words = [w.strip() for w in line.split(',')]
            opts = dict((w.split('=', 1) + [''])[:2] for w in words[1:])
            opts = {k.strip().upper(): v.strip() for k, v in opts.items()}
            block = words[0].upper()
            if block == '*ELEMENT':
                etype = opts['TYPE'].upper()
            elif block == '*NSET':
                nset, generate = opts['NSET'].upper(), 'GENERATE' in opts
                nsets.setdefault(nset, [])
            continue
        values = [v.strip() for v in line.split(',')]
        if block == '*NODE':
            nodes[int(values[0])] = [float(v) for v in values[1:] if v]
        elif block == '*ELEMENT':
            ids = [int(v) for v in values if v]
            pending = ids if pending is None else pending + ids
            if line.endswith(','):
                continue        # the element's labels go on on the next line
            elements.append((etype, pending[0], pending[1:]))
            pending = None
        elif block == '*NSET':
            ids = [int(v) for v in values if v]
            nsets[nset] += list(range(ids[0], ids[1] + 1, ids[2] if len(ids) > 2 else 1)) if generate else ids
    return nodes, elements, nsets
