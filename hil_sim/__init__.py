"""HIL simulator: firmware ELF images on simavr, UART/IR bus, hex-lattice plant.

``Simulator`` and ``load_scenario`` import without the C extension; building a
``Simulator`` needs it and says how to build it when it is missing.
"""

from .scenario import Scenario, load_scenario
from .simulator import Simulator

__all__ = ["Scenario", "Simulator", "load_scenario"]
