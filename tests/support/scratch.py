"""A unittest case with a temporary folder of its own, made before each test and removed after
it (the CLI tests write their inputs and outputs there)."""
import os
import tempfile
import unittest


class ScratchTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def path(self, name):
        """name inside the test's folder."""
        return os.path.join(self.dir.name, name)
