"""The web server of ``poinsot lab``: serves the built browser lab (``poinsot/lab/``, shipped in
the package) on the loopback interface, and nothing else.

Safety rules, each pinned by ``python/tests/test_lab_server.py``:

* it binds to ``127.0.0.1`` only (any other address is refused before a socket is opened);
* it serves regular files inside the page's directory only: a path with a ``..`` or ``.``
  segment, a backslash, a NUL, an encoded separator, or one that resolves (symbolic links
  followed) outside the directory gets 404, as does anything that is not a regular file;
* it answers ``GET`` and ``HEAD`` only (405 otherwise) and only to requests addressed to
  the loopback host (a ``Host`` header naming another host gets 404 too: DNS rebinding);
* responses carry ``X-Content-Type-Options: nosniff`` and a Content-Security-Policy that allows
  the page's own scripts and WebAssembly and nothing from elsewhere.
"""

from __future__ import annotations

import http.server
import socketserver
import threading
import urllib.parse
from pathlib import Path
from typing import Any, Optional

#: The only interface the lab binds to.
LOOPBACK = "127.0.0.1"

#: Content types of the files a built page contains (anything else: octet-stream).
CONTENT_TYPES = {
    ".html": "text/html; charset=utf-8",
    ".js": "text/javascript; charset=utf-8",
    ".mjs": "text/javascript; charset=utf-8",
    ".css": "text/css; charset=utf-8",
    ".wasm": "application/wasm",
    ".json": "application/json",
    ".svg": "image/svg+xml",
    ".png": "image/png",
    ".ico": "image/x-icon",
    ".txt": "text/plain; charset=utf-8",
    ".stl": "model/stl",
}

#: The page's own scripts, styles and WebAssembly; nothing from elsewhere.
CONTENT_SECURITY_POLICY = (
    "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self' 'unsafe-inline'; "
    "img-src 'self' data: blob:; connect-src 'self'; object-src 'none'; base-uri 'none'; "
    "frame-ancestors 'none'"
)


def page_dir() -> Path:
    """The directory of the built page inside the installed package (may not exist)."""
    return Path(__file__).resolve().parent / "lab"


def resolve_request(root: Path, raw_path: str) -> Optional[Path]:
    """The file under ``root`` that the request path ``raw_path`` names, or None (→ 404).

    ``/`` names ``index.html``. The query string and fragment are ignored. Refused: any
    ``..``/``.`` segment (raw or percent-encoded), backslashes, NUL, encoded ``/``, paths that
    resolve outside ``root`` (symbolic links followed), and anything but a regular file.
    """
    path = urllib.parse.urlsplit(raw_path).path
    if not path.startswith("/") or "%2f" in path.lower() or "%5c" in path.lower():
        return None
    decoded = urllib.parse.unquote(path, errors="strict") if "%" in path else path
    if "\x00" in decoded or "\\" in decoded:
        return None
    parts = decoded.split("/")[1:]
    if any(p in ("..", ".") for p in parts):
        return None
    parts = [p for p in parts if p]
    if not parts:
        parts = ["index.html"]
    base = root.resolve()
    candidate = (base.joinpath(*parts)).resolve()
    try:
        candidate.relative_to(base)
    except ValueError:
        return None
    return candidate if candidate.is_file() else None


class LabHandler(http.server.BaseHTTPRequestHandler):
    """Serves the files of ``server.root`` (see :func:`resolve_request`)."""

    server: "LabServer"
    server_version = "poinsot-lab"
    sys_version = ""

    def _allowed_host(self) -> bool:
        host = (self.headers.get("Host") or "").strip().lower()
        port = self.server.server_address[1]
        return host in {f"127.0.0.1:{port}", f"localhost:{port}", "127.0.0.1", "localhost"}

    def _send(self, status: int, body: bytes, content_type: str, head_only: bool) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("X-Content-Type-Options", "nosniff")
        self.send_header("Content-Security-Policy", CONTENT_SECURITY_POLICY)
        self.send_header("Cache-Control", "no-cache")
        self.end_headers()
        if not head_only:
            self.wfile.write(body)

    def _serve(self, head_only: bool) -> None:
        if not self._allowed_host():
            self._send(404, b"not found\n", "text/plain; charset=utf-8", head_only)
            return
        try:
            target = resolve_request(self.server.root, self.path)
        except (UnicodeDecodeError, ValueError):
            target = None
        if target is None:
            self._send(404, b"not found\n", "text/plain; charset=utf-8", head_only)
            return
        body = target.read_bytes()
        self._send(200, body, CONTENT_TYPES.get(target.suffix.lower(), "application/octet-stream"), head_only)

    def do_GET(self) -> None:  # noqa: N802 (the http.server API)
        self._serve(head_only=False)

    def do_HEAD(self) -> None:  # noqa: N802
        self._serve(head_only=True)

    def _refuse(self) -> None:
        self._send(405, b"method not allowed\n", "text/plain; charset=utf-8", head_only=False)

    do_POST = do_PUT = do_DELETE = do_PATCH = do_OPTIONS = _refuse  # noqa: N815

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002
        if self.server.verbose:
            super().log_message(format, *args)


class LabServer(socketserver.ThreadingMixIn, http.server.HTTPServer):
    """A threaded HTTP server bound to the loopback interface, serving ``root``."""

    daemon_threads = True
    allow_reuse_address = True

    def __init__(self, root: Path, port: int = 0, *, host: str = LOOPBACK, verbose: bool = False) -> None:
        if host != LOOPBACK:
            raise ValueError(f"host: the lab binds to {LOOPBACK} only, got {host!r}")
        if not 0 <= int(port) <= 65535:
            raise ValueError(f"port: must be in [0, 65535], got {port}")
        self.root = Path(root).resolve()
        self.verbose = verbose
        super().__init__((host, int(port)), LabHandler)

    @property
    def url(self) -> str:
        """The page's address, ``http://127.0.0.1:<port>/``."""
        return f"http://{LOOPBACK}:{self.server_address[1]}/"


def start_in_thread(root: Path, port: int = 0) -> LabServer:
    """A :class:`LabServer` already serving from a daemon thread (tests, notebooks);
    stop it with ``server.shutdown(); server.server_close()``."""
    server = LabServer(root, port)
    threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.05}, name="poinsot-lab", daemon=True).start()
    return server
