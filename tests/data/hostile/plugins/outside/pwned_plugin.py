# A plugin file outside the world's folder: importing it leaves a marker in the working folder.
from pathlib import Path

Path("pwned_by_plugin").write_text("this file ran")
