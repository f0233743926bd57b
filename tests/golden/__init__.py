"""Golden (regression) files: every shipped deck's per-angle columns and metrics."""
