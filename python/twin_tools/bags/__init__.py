"""Reading a run's bag: opening it (reader), plotting fields (plot), replaying it (replay)."""
