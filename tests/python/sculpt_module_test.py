# SPDX-License-Identifier: Apache-2.0
"""The Python module as a script or a notebook uses it: documents made, imported, edited and
measured by the same code as the sculpt program (their files equal byte for byte), numpy
meshes, progress callbacks, Ctrl-C, and other Python threads running during long work.
Run by ctest with PYTHONPATH at the built module and SCULPT at the built program."""
import math
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy

import sculpt

SCULPT = os.environ["SCULPT"]
DATA = os.environ["SCULPT_DATA_DIR"]


def run_sculpt(*args, cwd):
    subprocess.run([SCULPT, *args, "--quiet"], cwd=cwd, check=True)


def file_bytes(path):
    with open(path, "rb") as f:
        return f.read()


class SculptModule(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.path = self.dir.name

    def tearDown(self):
        self.dir.cleanup()

    def test_a_new_ball_meshes_as_numpy_arrays_and_measures_as_info_json(self):
        ball = sculpt.new(radius=10.0, voxel_size=0.5)
        vertices, triangles = ball.mesh()
        self.assertEqual(vertices.shape[1], 3)
        self.assertEqual(triangles.shape[1], 3)
        self.assertEqual(vertices.dtype, numpy.float32)
        self.assertGreater(len(triangles), 1000)
        self.assertLess(int(triangles.max()), len(vertices))
        radii = numpy.linalg.norm(vertices, axis=1)
        self.assertLess(abs(radii.mean() - 10.0), 0.05)
        info = ball.info()
        self.assertEqual(info["euler_characteristic"], 2)
        self.assertAlmostEqual(info["volume"], 4.0 / 3.0 * math.pi * 1000.0, delta=0.01 * 4189.0)
        # The same keys as the program's report of the same document saved.
        ball.save(os.path.join(self.path, "ball.vdb"))
        printed = subprocess.run([SCULPT, "info", "ball.vdb", "--json"], cwd=self.path, check=True,
                                 capture_output=True, text=True).stdout
        import json
        report = json.loads(printed)
        del report["command"], report["outputs"]
        self.assertEqual(info, report)

    def test_imports_equal_the_programs_byte_for_byte(self):
        run_sculpt("new", "--shape", "torus", "--radius", "8", "--voxel-size", "0.5", "-o", "ring.vdb",
                   "--mesh", "ring.stl", cwd=self.path)
        run_sculpt("import", "ring.stl", "--voxel-size", "0.4", "-o", "cli.vdb", cwd=self.path)
        sculpt.import_file(os.path.join(self.path, "ring.stl"), voxel_size=0.4).save(os.path.join(self.path, "py.vdb"))
        self.assertEqual(file_bytes(os.path.join(self.path, "cli.vdb")), file_bytes(os.path.join(self.path, "py.vdb")))
        # A label map of bare samples, a piece per label: the raw_ keywords are --raw-dims and the rest.
        ball = numpy.zeros((32, 32, 48), dtype=numpy.uint8)  # z, y, x: x varies fastest in the file
        z, y, x = numpy.mgrid[0:32, 0:32, 0:48]
        ball[numpy.maximum(numpy.maximum(abs(x - 15.5), abs(y - 15.5)), abs(z - 15.5)) < 10] = 1
        ball[numpy.sqrt((x - 31.5) ** 2 + (y - 15.5) ** 2 + (z - 15.5) ** 2) < 6] = 3
        ball.tofile(os.path.join(self.path, "map.raw"))
        run_sculpt("import", "map.raw", "--raw-dims", "48,32,32", "--labels", "--crop", "0,0,0,47,31,30", "-o",
                   "labels-cli.vdb", cwd=self.path)
        labels = sculpt.import_file(os.path.join(self.path, "map.raw"), raw_dims=(48, 32, 32), labels=True,
                                    crop=(0, 0, 0, 47, 31, 30))
        self.assertEqual(labels.pieces, ["label 1", "label 3"])
        labels.save(os.path.join(self.path, "labels-py.vdb"))
        self.assertEqual(file_bytes(os.path.join(self.path, "labels-cli.vdb")),
                         file_bytes(os.path.join(self.path, "labels-py.vdb")))
        scan = "/usr/share/mricron/templates/ch2bet.nii.gz"
        if os.path.exists(scan):
            run_sculpt("import", scan, "--voxel-size", "4", "-o", "brain-cli.vdb", cwd=self.path)
            sculpt.import_file(scan, voxel_size=4).save(os.path.join(self.path, "brain-py.vdb"))
            self.assertEqual(file_bytes(os.path.join(self.path, "brain-cli.vdb")),
                             file_bytes(os.path.join(self.path, "brain-py.vdb")))

    def test_edits_equal_the_programs_and_a_stroke_script_replays(self):
        run_sculpt("new", "-o", "clay.vdb", cwd=self.path)
        run_sculpt("apply", "clay.vdb", os.path.join(DATA, "strokes", "face.json"), "-o", "face-cli.vdb",
                   cwd=self.path)
        run_sculpt("smooth", "face-cli.vdb", "--iterations", "3", "-o", "smooth-cli.vdb", cwd=self.path)
        clay = sculpt.open(os.path.join(self.path, "clay.vdb"))
        done = clay.apply(os.path.join(DATA, "strokes", "face.json"))
        self.assertGreater(done["strokes"], 10)
        clay.smooth(iterations=3)
        clay.save(os.path.join(self.path, "smooth-py.vdb"))
        self.assertEqual(file_bytes(os.path.join(self.path, "smooth-cli.vdb")),
                         file_bytes(os.path.join(self.path, "smooth-py.vdb")))

    def test_offset_hollow_islands_and_morph(self):
        ball = sculpt.new(radius=6.0, voxel_size=0.5)
        before = ball.info()["volume"]
        ball.offset(1.0)
        self.assertAlmostEqual(ball.info()["volume"], 4.0 / 3.0 * math.pi * 7.0 ** 3, delta=0.02 * 1437.0)
        ball.hollow(thickness=1.5)
        self.assertEqual(ball.info()["components"], 2)  # the outside and the cavity's wall
        ball.remove_islands(under=1.0)
        box = sculpt.new(shape="box", radius=5.0, voxel_size=0.5)
        box.save(os.path.join(self.path, "box.vdb"))
        start = sculpt.new(radius=6.0, voxel_size=0.5)
        result = start.morph(os.path.join(self.path, "box.vdb"), frames=3)
        self.assertEqual(len(result["frames"]), 3)
        self.assertAlmostEqual(result["frames"][-1].info()["volume"], 1000.0, delta=20.0)
        self.assertGreater(before, 0.0)

    def test_progress_rises_and_false_cancels_leaving_the_document_as_it_was(self):
        ball = sculpt.new(radius=10.0, voxel_size=0.5)
        seen = []
        ball.smooth(iterations=20, progress=lambda f: seen.append(f))
        self.assertGreater(len(seen), 2)
        self.assertEqual(seen, sorted(seen))
        self.assertLessEqual(seen[-1], 1.0)
        kept = ball.info()
        with self.assertRaises(sculpt.Cancelled):
            ball.smooth(iterations=50, progress=lambda f: f < 0.3)
        self.assertEqual(ball.info(), kept)

    def test_ctrl_c_raises_keyboard_interrupt_and_the_callbacks_own_error_comes_through(self):
        ball = sculpt.new(radius=10.0, voxel_size=0.5)
        kept = ball.info()

        def interrupt(fraction):
            if fraction > 0.1:
                os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C in the terminal

        with self.assertRaises(KeyboardInterrupt):
            ball.smooth(iterations=200, progress=interrupt)
        self.assertEqual(ball.info(), kept)

        def broken(fraction):
            raise ZeroDivisionError("the caller's own mistake")

        with self.assertRaises(ZeroDivisionError):
            ball.offset(1.0, progress=broken)
        self.assertEqual(ball.info(), kept)

    def test_other_threads_run_while_the_engine_works(self):
        ball = sculpt.new(radius=20.0, voxel_size=0.5)
        ticks = []
        stop = threading.Event()

        def count():
            while not stop.is_set():
                ticks.append(time.monotonic())
                time.sleep(0.001)

        counter = threading.Thread(target=count)
        counter.start()
        started = time.monotonic()
        ball.smooth(iterations=30)
        ended = time.monotonic()
        stop.set()
        counter.join()
        during = [t for t in ticks if started < t < ended]
        self.assertGreater(ended - started, 0.2)
        self.assertGreater(len(during), 20, "the GIL was held during the smoothing")

    def test_bad_input_is_a_value_error_naming_the_file(self):
        with self.assertRaises(ValueError) as raised:
            sculpt.open(os.path.join(self.path, "missing.vdb"))
        self.assertIn("missing.vdb", str(raised.exception))
        self.assertTrue(issubclass(sculpt.InputError, ValueError))
        with self.assertRaises(ValueError):
            sculpt.new(shape="cone")


if __name__ == "__main__":
    unittest.main(verbosity=2)
