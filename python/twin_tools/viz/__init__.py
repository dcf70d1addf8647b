"""The live view in rviz: the node, what it draws (layout) and its drawing primitives (markers)."""
