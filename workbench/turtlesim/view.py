"""The turtlesim canvas, live in a browser: a tiny HTTP server on 127.0.0.1.

``/`` is a page that reloads ``/canvas.png`` about 15 times a second;
``/canvas.png`` renders the current canvas with its turtles.
"""

from __future__ import annotations

import io
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any

_PAGE = b"""<!doctype html>
<html><head><meta charset="utf-8"><title>TurtleSim</title>
<style>body{background:#222;margin:0;display:flex;justify-content:center;align-items:center;
height:100vh}img{width:500px;height:500px;image-rendering:pixelated}</style></head>
<body><img id="c" src="canvas.png" alt="turtlesim canvas">
<script>
const img = document.getElementById("c");
function next() { const n = new Image(); n.onload = () => { img.src = n.src; setTimeout(next, 66); };
  n.onerror = () => setTimeout(next, 1000); n.src = "canvas.png?t=" + Date.now(); }
setTimeout(next, 66);
</script></body></html>
"""


class CanvasServer:
    """Serve a turtlesim's canvas.

    Args:
        source: Anything with ``lock`` and ``sim`` (a :class:`TurtlesimNode`), or a
            :class:`~workbench.turtlesim.sim.TurtleSim` itself.
        port: TCP port on 127.0.0.1; 0 picks a free one.
    """

    def __init__(self, source: Any, port: int = 0) -> None:
        self.source = source
        server = self

        class Handler(BaseHTTPRequestHandler):
            def do_GET(self) -> None:  # noqa: N802 (http.server's name)
                if self.path == "/" or self.path.startswith("/index"):
                    body, kind = _PAGE, "text/html"
                elif self.path.startswith("/canvas.png"):
                    body, kind = server.png_bytes(), "image/png"
                else:
                    self.send_error(404)
                    return
                self.send_response(200)
                self.send_header("Content-Type", kind)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.end_headers()
                self.wfile.write(body)

            def log_message(self, *args: Any) -> None:
                pass

        self._httpd = ThreadingHTTPServer(("127.0.0.1", port), Handler)
        self._thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        host, port = self._httpd.server_address[:2]
        if isinstance(host, bytes):
            host = host.decode()
        return f"http://{host}:{port}/"

    def png_bytes(self) -> bytes:
        """The current canvas as PNG bytes."""
        sim = getattr(self.source, "sim", self.source)
        lock = getattr(self.source, "lock", None)
        if lock is not None:
            with lock:
                image = sim.render()
        else:
            image = sim.render()
        buffer = io.BytesIO()
        image.save(buffer, format="PNG")
        return buffer.getvalue()

    def start(self) -> None:
        self._thread = threading.Thread(target=self._httpd.serve_forever, daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._httpd.shutdown()
        self._httpd.server_close()
