"""A corpus input copied into a scratch directory of its own, with the .node beside a .poly that
reads its vertices from it (shared by the corpus scripts of tests/bench)."""
import os
import shutil
import tempfile


def scratch_copy(path):
    """Returns a new temporary directory holding path (and path's .node when path is a .poly)."""
    d = tempfile.mkdtemp()
    shutil.copy(path, d)
    node = path[:-5] + '.node'
    if path.endswith('.poly') and os.path.exists(node):
        shutil.copy(node, d)
    return d
