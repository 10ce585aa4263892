"""What users run: sweeps, rig logs, spin-down, plots and the command line."""
