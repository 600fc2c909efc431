"""Planners and lattice algorithms: hex reconfiguration, square-lattice locomotion."""
