"""Where the package finds the rest of the repository: REPO is the checkout this package lives in
(python/twin_tools/ under it), whether imported from the source folder (PYTHONPATH=REPO/python)
or through the catkin devel space's relay (build/devel/.../twin_tools/__init__.py)."""
import os

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
