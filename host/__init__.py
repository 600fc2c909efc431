"""Host side: Textual console, CLI tools, serial links."""
