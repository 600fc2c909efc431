"""The Textual console: the thesis' VB GUI, in the terminal."""
