"""Programming the modules' ATmega162s: avrdude runner, fuse safety, CLI."""
