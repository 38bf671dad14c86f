"""ldfcz_tools.outputs against the outputs of a real short run (decks/single/cohesive_block.inp, 23 increments,
about 0.1 s): the summary's counters against the CSV, the status file and the frames the same run wrote, and the
reader's refusals (another JSON, another layout, a truncated file). LDFCZ_EXE names the program (CTest sets it);
LDFCZ_DECKS the deck folder (default decks/ of the source tree)."""
import json
import os
import re
import shutil
import subprocess
import tempfile
import unittest

from ldfcz_tools import outputs
from ldfcz_tools.paths import ROOT

JOB = 'cohesive_block'


def setUpModule():
    global WORK, SUMMARY
    exe = os.environ.get('LDFCZ_EXE', os.path.join(ROOT, 'build', 'bin', 'ldfcz'))
    if not os.path.exists(exe):
        raise unittest.SkipTest('no ldfcz program (set LDFCZ_EXE)')
    deck = os.path.join(os.environ.get('LDFCZ_DECKS', os.path.join(ROOT, 'decks')), 'single', JOB + '.inp')
    WORK = tempfile.mkdtemp(prefix='ldfcz_tools_')
    subprocess.run([exe, '-q', '-t', '1', '-o', WORK, deck], check=True, timeout=120)
    SUMMARY = outputs.read_summary(WORK, JOB)


def tearDownModule():
    shutil.rmtree(WORK, ignore_errors=True)


class RealRun(unittest.TestCase):

    def test_summary(self):
        self.assertEqual(SUMMARY['status'], 'completed')
        self.assertEqual(SUMMARY['exit_code'], 0)
        self.assertEqual(outputs.get(SUMMARY, 'model.nodes'), 12)
        self.assertIsNone(outputs.get(SUMMARY, 'restart.from'))
        self.assertEqual(outputs.get(SUMMARY, 'no.such.key', 'x'), 'x')
        self.assertIn('steps[].external_work', outputs.summary_keys(SUMMARY))
        self.assertEqual(outputs.summary_nonfinite(SUMMARY), [])

    def test_csv_against_summary(self):
        # one row per converged increment; the last row is the last step's last increment at its total time (the
        # CSV's 16 digits against the summary's 17)
        rows = outputs.read_csv(os.path.join(WORK, JOB + '.csv'))
        self.assertEqual(len(rows), SUMMARY['counters']['increments'])
        last = SUMMARY['steps'][-1]
        self.assertEqual((rows[-1]['step'], rows[-1]['inc']), (last['step'], last['increments']))
        self.assertAlmostEqual(rows[-1]['total_time'], last['total_time'], delta=1e-15 * abs(last['total_time']))
        header, data = outputs.read_csv_columns(os.path.join(WORK, JOB + '.csv'))
        self.assertEqual(header[:4], ['step', 'inc', 'step_time', 'total_time'])
        self.assertEqual(len(data), len(rows))

    def test_sta_against_summary(self):
        # one line per attempt, converged or cut back; the iterations add up to the summary's
        sta = outputs.read_sta(os.path.join(WORK, JOB + '.sta'))
        self.assertEqual(len(sta), SUMMARY['counters']['attempts'])
        self.assertTrue(all(r['outcome'] == 'converged' and len(r['ratios']) == r['iterations'] + 1 for r in sta))
        counts = outputs.sta_counts(os.path.join(WORK, JOB + '.sta'))
        self.assertEqual(counts, {k: SUMMARY['counters'][k] for k in counts})

    def test_frames(self):
        # frame 1 is the initial state; the times increase to the last increment's
        frames = outputs.pvd_frames(os.path.join(WORK, JOB + '.pvd'))
        listed = [f for f in os.listdir(WORK) if re.match(re.escape(JOB) + r'_\d{4}\.vtm$', f)] or \
            [f for f in os.listdir(WORK) if re.match(re.escape(JOB) + r'_\d{4}\.vtu$', f)]
        self.assertEqual(len(frames), len(listed))
        # a model of continuum and user elements: each frame a .vtm of the two blocks, each block's file there
        for _, f in frames:
            blocks = outputs.frame_files(os.path.join(WORK, f))
            if f.endswith('.vtm'):
                self.assertEqual(sorted(blocks), ['continuum', 'interface'])
            self.assertTrue(all(os.path.exists(x) for files in blocks.values() for x in files))
        times = [t for t, _ in frames]
        self.assertEqual(times[0], 0.0)
        self.assertEqual(times, sorted(times))
        self.assertAlmostEqual(times[-1], SUMMARY['steps'][-1]['total_time'], delta=1e-15)


    def test_study_frames_see_the_interface_block(self):
        # the cohesive cells are written in a block of their own (JOB_NNNN_interface.vtu): the peel study's frame
        # readers must find them there. With delta = half the largest opening of the last frame, that cell's opening
        # lies in (delta, 6 delta), so the softening zone holds at least one cell and the front is found.
        from ldfcz_tools import peel_study
        frames = peel_study.vtu_frames(WORK)
        self.assertGreater(len(frames), 0)
        files = peel_study.with_interface_blocks(frames[-1])
        self.assertIn(os.path.join(WORK, JOB + '_%04d_interface.vtu' % len(frames)), files)
        openings = [a['opening'] for a in (peel_study.read_vtu_arrays(v, ('opening',))[1] for v in files)
                    if a['opening']]
        self.assertEqual(len(openings), 1)
        d = max(sum(c * c for c in o[3 * i:3 * i + 3]) ** 0.5 for o in openings for i in range(len(o) // 3))
        self.assertGreater(d, 0.0)
        cells, _ = peel_study.process_zone(frames[-1], 0.5 * d)
        self.assertGreaterEqual(cells, 1)
        self.assertIsNotNone(peel_study.frame_front(frames[-1], 0.5 * d))


class Refusals(unittest.TestCase):

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, 'w') as f:
            f.write(text)
        return path

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix='ldfcz_tools_')

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def test_refusals(self):
        self.assertIsNone(outputs.read_summary(self.dir, 'none'))
        with open(outputs.summary_path(WORK, JOB)) as f:
            text = f.read()
        with self.assertRaises(outputs.SummaryError):
            outputs.read_summary_file(self.write('half.summary.json', text[:len(text) // 2]))
        with self.assertRaises(outputs.SummaryError):
            outputs.read_summary_file(self.write('other.json', json.dumps({'schema': 'something else'})))
        doc = json.loads(text)
        doc['schema_version'] = 99
        with self.assertRaises(outputs.SummaryError):
            outputs.read_summary_file(self.write('future.summary.json', json.dumps(doc)))
        doc['schema_version'] = 1
        doc['energy']['external_work'] = None
        self.assertEqual(outputs.summary_nonfinite(doc), ['energy.external_work'])


if __name__ == '__main__':
    unittest.main()
