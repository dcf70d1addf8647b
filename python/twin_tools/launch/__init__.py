"""Launch arguments and launching a launch file on its own ROS master."""
