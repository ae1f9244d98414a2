"""The farm's judgement of files (pipelines/farm/dewpoint_farm) against files
written, and counts reported, by tools that are not dewpoint's: assimp
writes and reads the PLYs, oiiotool writes the images."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "pipelines", "farm"))

from dewpoint_farm.frame_range import UsageError, frames_to_process, parse_frame_range, slurm_index_list  # noqa: E402
from dewpoint_farm.ply_check import ply_element_counts  # noqa: E402
from dewpoint_farm.shot_state import images_readable  # noqa: E402

SOURCE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
TRAY = os.path.join(SOURCE_DIR, "assets", "meshes", "tray.obj")


def run(*command):
    return subprocess.run(command, capture_output=True, text=True, check=True).stdout


def assimp_counts(ply):
    info = run("assimp", "info", ply)
    return {"vertex": int(re.search(r"^Vertices:\s*(\d+)", info, re.M).group(1)),
            "face": int(re.search(r"^Faces:\s*(\d+)", info, re.M).group(1))}


def truncate_by(path, nbytes):
    with open(path, "r+b") as f:
        f.truncate(os.path.getsize(path) - nbytes)


class PlyWholeness(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.triangles = os.path.join(self.dir.name, "tray.ply")
        run("assimp", "export", TRAY, self.triangles, "-fplyb", "-tri")

    def tearDown(self):
        self.dir.cleanup()

    def test_counts_of_a_whole_file_are_assimps(self):
        self.assertEqual(ply_element_counts(self.triangles), assimp_counts(self.triangles))

    def test_a_file_one_byte_short_is_not_whole(self):
        truncate_by(self.triangles, 1)
        self.assertIsNone(ply_element_counts(self.triangles))

    def test_a_file_with_trailing_bytes_is_not_whole(self):
        with open(self.triangles, "ab") as f:
            f.write(b"\0")
        self.assertIsNone(ply_element_counts(self.triangles))

    def test_a_header_cut_off_is_not_whole(self):
        with open(self.triangles, "r+b") as f:
            f.truncate(40)
        self.assertIsNone(ply_element_counts(self.triangles))

    def test_quads_and_ascii_are_not_taken_for_whole_dewpoint_files(self):
        quads = os.path.join(self.dir.name, "quads.ply")
        ascii_ply = os.path.join(self.dir.name, "ascii.ply")
        run("assimp", "export", TRAY, quads, "-fplyb")
        run("assimp", "export", TRAY, ascii_ply, "-fply", "-tri")
        self.assertIsNone(ply_element_counts(quads))
        self.assertIsNone(ply_element_counts(ascii_ply))

    def test_a_missing_file_is_not_whole(self):
        self.assertIsNone(ply_element_counts(os.path.join(self.dir.name, "none.ply")))


class ImageReadability(unittest.TestCase):
    def test_truncated_exr_with_intact_header_is_unreadable(self):
        with tempfile.TemporaryDirectory() as d:
            exr, png = os.path.join(d, "a.exr"), os.path.join(d, "a.png")
            run("oiiotool", "--pattern", "noise", "128x64", "4", "-d", "float", "-o", exr)
            run("oiiotool", "--pattern", "noise", "128x64", "3", "-d", "uint8", "-o", png)
            self.assertTrue(images_readable(exr, png))
            truncate_by(exr, os.path.getsize(exr) // 2)
            self.assertIn("128 x", run("oiiotool", "--info", exr))  # the header still reads
            self.assertFalse(images_readable(exr, png))
            self.assertFalse(images_readable(png, os.path.join(d, "none.exr")))


class FrameLists(unittest.TestCase):
    def test_slurm_array_syntax(self):
        self.assertEqual(slurm_index_list([7, 1, 2, 3, 9, 10]), "1-3,7,9-10")
        self.assertEqual(slurm_index_list([4]), "4")

    def test_requested_range_is_clipped_to_the_scene(self):
        self.assertEqual(frames_to_process(3, parse_frame_range("2-")), [2, 3])
        self.assertEqual(frames_to_process(3, parse_frame_range("1-9")), [1, 2, 3])
        self.assertEqual(frames_to_process(3, parse_frame_range("2")), [2])
        self.assertEqual(frames_to_process(3, None), [0, 1, 2, 3])

    def test_bad_ranges_name_the_option(self):
        for text in ("x", "3-1", "-2", "1-b"):
            with self.assertRaisesRegex(UsageError, "--frames"):
                frames_to_process(10, parse_frame_range(text))
        with self.assertRaisesRegex(UsageError, "past the scene's last frame 3"):
            frames_to_process(3, parse_frame_range("4-5"))


if __name__ == "__main__":
    unittest.main()
