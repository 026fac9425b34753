"""The logic behind the node/topic/service/param/msg/srv tools.

Formatting and parsing live here, free of argparse, so the command line,
notebooks and tests share them: YAML arguments (``args``), ``echo`` text and
field paths (``echo``), ``hz``/``bw`` statistics (``rates``), message and
service definitions (``definitions``) and graph queries (``graph``).
"""
