# The twin's Python tools, package twin_tools under python/ (catkin_python_setup in CMakeLists.txt
# puts it on the devel space's PYTHONPATH; not for running by hand).
from setuptools import find_packages, setup

from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=find_packages("python"), package_dir={"": "python"}))
