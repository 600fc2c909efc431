"""Suite-wide settings.

Under CI (``CI`` set) hypothesis runs derandomized: the same examples every
run, so a red build is reproducible and never depends on luck. Locally it
explores new examples each run.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, deadline=None)
settings.register_profile("dev", deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")
