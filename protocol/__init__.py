"""The HexBot wire protocol: function codes, frame codecs, reply parser."""
