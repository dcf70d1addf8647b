"""Opening a run's bag for the tools (report, plot, replay, diagnostics): every unreadable input
is answered with a message naming the file, what is wrong with it and what to do, never a
traceback. The classes: no such path, a folder, an empty file, a file that is not a ROS bag, a
bag cut short (not indexed: `rosbag reindex` rebuilds the index from what was written), and any other
unreadable bag. (A readable bag that lacks some topics is each tool's own case: the report writes
what the bag holds, plot and replay name the missing topic.)"""
import os

BAG_MAGIC = b"#ROSBAG V2.0\n"  # the first line of every ROS bag format 2.0 file


class BagError(Exception):
    """An input that is not a readable bag (or lacks what the tool needs); str() is the message."""


def check_bag_file(path):
    """BagError naming path unless it is a file that starts as a ROS bag format 2.0."""
    if not os.path.exists(path):
        raise BagError("%s: no such file" % path)
    if os.path.isdir(path):
        raise BagError("%s: a folder, not a bag (a run's bag is DIR/run.bag)" % path)
    if os.path.getsize(path) == 0:
        raise BagError("%s: an empty file, not a bag" % path)
    try:
        with open(path, "rb") as f:
            head = f.read(len(BAG_MAGIC))
    except OSError as e:
        raise BagError("%s: cannot be read: %s" % (path, e.strerror or e))
    if head != BAG_MAGIC:
        raise BagError("%s: not a ROS bag (it does not start with '#ROSBAG V2.0')" % path)


def open_bag(path, mode="r"):
    """rosbag.Bag opened for reading (mode "r") or appending ("a"); BagError naming path and cause
    otherwise."""
    check_bag_file(path)
    import rosbag
    try:
        return rosbag.Bag(path, mode)
    except rosbag.ROSBagUnindexedException:
        raise BagError("%s: the bag was cut short (it has no index: the run or the copy was interrupted "
                       "before the bag was closed). `rosbag reindex %s` rebuilds the index from what was "
                       "written (the original is kept as .orig.bag); `scripts/twin plot` then reads that "
                       "stretch" % (path, path))
    except Exception as e:  # rosbag raises ROSBagException, ROSBagFormatException, struct errors...
        raise BagError("%s: not a readable bag: %s" % (path, e or type(e).__name__))

