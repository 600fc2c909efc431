"""HIL simulator: firmware ELF images on simavr, UART/IR bus, hex-lattice plant."""
