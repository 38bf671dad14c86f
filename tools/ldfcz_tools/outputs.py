"""Reading a run's outputs: JOB.summary.json (the closing summary, docs/summary.md), JOB.csv (history rows), JOB.sta
(one line per increment attempt) and JOB.pvd (the frames' times). The tools read runs only through these
functions; none of them parses JOB.log, which is for people."""
import csv
import json
import os
import re

SUMMARY_SCHEMA = 'ldfcz run summary'
SUMMARY_VERSIONS = (1,)          # the summary layouts this module reads (docs/summary.md, schema_version)


class SummaryError(ValueError):
    """A file that is not a run summary this module can read."""


def summary_path(outdir, job):
    """DIR/JOB.summary.json."""
    return os.path.join(outdir, job + '.summary.json')


def read_summary_file(path):
    """The summary document at path (a dict); None when there is no file (the run has not ended, ended before it
    got past its deck, or was killed outright: docs/summary.md). SummaryError for a file of another kind or layout."""
    try:
        with open(path, encoding='utf-8') as f:
            doc = json.load(f)
    except FileNotFoundError:
        return None
    except json.JSONDecodeError as e:
        raise SummaryError('%s: not JSON (%s)' % (path, e)) from None
    if not isinstance(doc, dict) or doc.get('schema') != SUMMARY_SCHEMA:
        raise SummaryError('%s: not an ldfcz run summary' % path)
    if doc.get('schema_version') not in SUMMARY_VERSIONS:
        raise SummaryError('%s: summary layout %r, this reader knows %s' % (path, doc.get('schema_version'),
                                                                         SUMMARY_VERSIONS))
    return doc


def read_summary(outdir, job):
    """The summary of job JOB in output directory DIR (read_summary_file)."""
    return read_summary_file(summary_path(outdir, job))


def get(doc, key, default=None):
    """The value at a dotted key ('counters.increments'); default when a member on the way is missing or null."""
    v = doc
    for part in key.split('.'):
        if not isinstance(v, dict) or v.get(part) is None:
            return default
        v = v[part]
    return v


def summary_keys(doc, prefix=''):
    """Every key of a document as docs/summary.md names them: dotted members, 'steps[].x' for the members of the
    objects in an array."""
    keys = set()
    for k, v in doc.items():
        name = prefix + k
        keys.add(name)
        if isinstance(v, dict):
            keys |= summary_keys(v, name + '.')
        elif isinstance(v, list):
            for item in v:
                if isinstance(item, dict):
                    keys |= summary_keys(item, name + '[].')
    return keys


def summary_nonfinite(doc):
    """Keys of figures a run that reached its first step always measures, written as null (the summary writes a NaN
    or an infinity as null): empty for a sound run."""
    if get(doc, 'times.wall_s') is None:
        return []
    must = ['times.' + k for k in doc['times']] + ['energy.external_work', 'accuracy.max_opening_ratio']
    bad = [k for k in must if get(doc, k) is None]
    bad += ['steps[%d].external_work' % i for i, s in enumerate(doc.get('steps', []))
            if s.get('increments', 0) > 0 and s.get('external_work') is None]
    return bad


def read_csv(path):
    """JOB.csv as a list of rows, each a dict of column name to float (step and inc too); [] when absent."""
    if not os.path.exists(path):
        return []
    with open(path, newline='') as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def read_csv_columns(path):
    """JOB.csv as (header, rows): the column names and each row as a list of floats."""
    with open(path) as f:
        lines = [ln.strip() for ln in f if ln.strip()]
    if not lines:
        return [], []
    return lines[0].split(','), [[float(x) for x in ln.split(',')] for ln in lines[1:]]


def read_sta(path):
    """JOB.sta's attempts: dicts with step, inc, attempt, iterations (ints), step_time, dt (floats), outcome
    ('converged', 'cutback: ...'; a *MONITOR value follows 'converged') and ratios (the r/q values). Notes (lines
    starting with '#') are skipped. [] when absent."""
    rows = []
    if not os.path.exists(path):
        return rows
    with open(path, errors='replace') as f:
        for line in f:
            w = line.split()
            if len(w) < 7 or w[0].startswith('#'):
                continue
            rest = ' '.join(w[6:])
            outcome, _, ratios = rest.partition(' r/q:')
            rows.append(dict(step=int(w[0]), inc=int(w[1]), attempt=int(w[2]), iterations=int(w[3]),
                             step_time=float(w[4]), dt=float(w[5]), outcome=outcome.strip(),
                             ratios=[float(x) for x in ratios.split()]))
    return rows


def sta_counts(path):
    """Increments, attempts, cutbacks and Newton iterations counted from JOB.sta (for a run without a summary)."""
    out = {'increments': 0, 'attempts': 0, 'cutbacks': 0, 'iterations': 0}
    for r in read_sta(path):
        out['attempts'] += 1
        out['iterations'] += r['iterations']
        if r['outcome'].startswith('converged'):
            out['increments'] += 1
        else:
            out['cutbacks'] += 1
    return out


def pvd_frames(path):
    """(total time, file) of each frame listed in JOB.pvd, in order; [] when absent. A frame's file is JOB_NNNN.vtu
    (one block), JOB_NNNN.pvtu (one block in pieces, a distributed run) or JOB_NNNN.vtm (two blocks: continuum and
    interface elements; frame_files lists its files)."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        text = f.read()
    return [(float(t), name) for t, name in re.findall(r'timestep="\s*([^"]+)"[^>]*file="([^"]+)"', text)]


def frame_files(path):
    """{block name: [the .vtu files of the block]} of one frame file (.vtu, .pvtu or .vtm). One block (.vtu, .pvtu)
    is named '' and holds every element; a .vtm names its blocks 'continuum' and 'interface' (the user elements);
    a block of a distributed run lists its processes' pieces JOB_NNNN[_interface]_R.vtu."""
    d = os.path.dirname(path)
    with open(path) as f:
        text = f.read()
    if path.endswith('.vtu'):
        return {'': [path]}
    if path.endswith('.pvtu'):
        return {'': [os.path.join(d, x) for x in re.findall(r'<Piece Source="([^"]+)"', text)]}
    if not path.endswith('.vtm'):
        raise ValueError('%s: not a frame file (.vtu, .pvtu or .vtm)' % path)
    blocks = {}
    for name, body in re.findall(r'<Block [^>]*name="([^"]*)"[^>]*>(.*?)</Block>', text, re.S):
        blocks[name] = [os.path.join(d, x) for x in re.findall(r'file="([^"]+)"', body)]
    for name, file in re.findall(r'<DataSet [^>]*name="([^"]*)"[^>]*file="([^"]+)"', re.sub(
            r'<Block .*?</Block>', '', text, flags=re.S)):
        blocks[name] = [os.path.join(d, file)]
    return blocks
