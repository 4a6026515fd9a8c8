"""The web server of ``poinsot lab``: serves the built browser lab (``poinsot/lab/``, shipped in
the package) on the loopback interface, and nothing else.

Safety rules, each pinned by ``python/tests/test_labserver.py``:

* it binds to ``127.0.0.1`` only (any other address is refused before a socket is opened);
* it serves regular files inside the page's directory only: a path with a ``..`` or ``.``
  segment, a backslash, a NUL, an encoded separator, or one that resolves (symbolic links
  followed) outside the directory gets 404, as does anything that is not a regular file, and
  any path the file system cannot even look up (a segment longer than :data:`MAX_SEGMENT`
  bytes: 404; a request path longer than :data:`MAX_REQUEST_PATH`: 414);
* it answers ``GET`` and ``HEAD`` only (405 otherwise) and only to requests addressed to
  the loopback host (a ``Host`` header naming another host gets 404 too: DNS rebinding);
* responses carry ``X-Content-Type-Options: nosniff`` and a Content-Security-Policy that allows
  the page's own scripts and WebAssembly and nothing from elsewhere.

Limits (docs/lab.md, "The server's limits"), so that no client can exhaust it:

* a connection costs no thread while its request is arriving: one selector thread watches up
  to :data:`MAX_PENDING` of them and closes any whose request has not arrived within
  :data:`CONNECTION_TIMEOUT_S` (idle or half-sent connections cannot hold a worker; past
  :data:`MAX_PENDING`, the oldest is closed); the listen queue is :data:`REQUEST_QUEUE_SIZE`
  deep (the standard library's 5 made parallel clients wait seconds for a retried connect);
* a complete request is answered by a worker thread, at most :data:`MAX_WORKERS` at once,
  whose every read and write times out after :data:`CONNECTION_TIMEOUT_S`;
* the whole request head has one deadline, :data:`CONNECTION_TIMEOUT_S` after the connection
  was accepted, counted across all its reads, in the selector and in the worker alike: a head
  handed to a worker unfinished (:data:`MAX_REQUEST_HEAD` bytes without the blank line) and
  then trickled a byte at a time (each read well inside its own timeout) is dropped at the
  deadline, so tricklers cannot hold the workers (issue 21, item 7);
* compressible files (HTML, JavaScript, CSS, JSON, SVG, WebAssembly, text) are sent
  gzip-compressed to clients that accept it (``Accept-Encoding``; ``Vary: Accept-Encoding``),
  compressed once and kept in memory until the file changes; every response has an exact
  ``Content-Length`` and an ``ETag`` (``If-None-Match`` answers 304).
"""

from __future__ import annotations

import gzip
import hashlib
import http.server
import io
import os
import selectors
import shutil
import socket
import sys
import threading
import time
import urllib.parse
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional, cast

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
    ".map": "application/json",
}

#: Suffixes worth compressing (text and WebAssembly; images are compressed already).
COMPRESSIBLE = frozenset(
    {".html", ".js", ".mjs", ".css", ".wasm", ".json", ".svg", ".txt", ".stl", ".map"}
)

#: The page's own scripts, styles and WebAssembly; nothing from elsewhere.
CONTENT_SECURITY_POLICY = (
    "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self' 'unsafe-inline'; "
    "img-src 'self' data: blob:; connect-src 'self'; object-src 'none'; base-uri 'none'; "
    "frame-ancestors 'none'"
)

#: Connections handled at once (one thread each). A browser opens at most six per host; the
#: rest of the headroom is for several tabs and reloads.
MAX_WORKERS = 32

#: Depth of the listen queue (the standard library's default is 5: with 200 parallel clients,
#: connections were dropped and retried after 1, 3, 7, ... s; the kernel caps it at somaxconn).
REQUEST_QUEUE_SIZE = 1024

#: Seconds any one read or write on a connection may block before the connection is dropped.
CONNECTION_TIMEOUT_S = 10.0

#: Accepted connections that may wait at once for their request to arrive (no thread each:
#: one file descriptor); past this, the one that has waited longest is closed.
MAX_PENDING = 512

#: A request head (request line and headers) arrived once it holds a blank line or reaches
#: this size (the handler then reads it, with the standard library's limits: 64 KiB a line).
MAX_REQUEST_HEAD = 65536

#: Longest request path answered (longer: 414 URI Too Long); the page's paths are < 100 bytes.
MAX_REQUEST_PATH = 2048

#: Longest path segment a file system can hold (NAME_MAX); longer: 404 without a lookup.
MAX_SEGMENT = 255

#: Files up to this size are read, compressed and kept in memory; larger ones (none in a built
#: page) are streamed from disk uncompressed.
MAX_CACHED_BYTES = 32 * 1024 * 1024

#: gzip level of the compressed copies (made once per file, so the slowest, smallest one).
GZIP_LEVEL = 9


def page_dir() -> Path:
    """The directory of the built page inside the installed package (may not exist)."""
    return Path(__file__).resolve().parent / "lab"


#: The lab as one self-contained HTML file (script, styles and WebAssembly inside; built by
#: web/vite.export.config.ts), beside the page in the package; `poinsot lab --export` copies it.
EXPORT_NAME = "poinsot-lab.html"


def export_file() -> Path:
    """The one-file lab inside the installed package (may not exist)."""
    return page_dir() / EXPORT_NAME


def resolve_request(root: Path, raw_path: str) -> Optional[Path]:
    """The file under ``root`` that the request path ``raw_path`` names, or None (→ 404).

    ``/`` names ``index.html``. The query string and fragment are ignored. Refused: any
    ``..``/``.`` segment (raw or percent-encoded), backslashes, NUL, encoded ``/``, segments
    longer than :data:`MAX_SEGMENT` bytes, paths that resolve outside ``root`` (symbolic links
    followed), any path the file system refuses to look up, and anything but a regular file.
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
    if any(len(p.encode("utf-8", "surrogatepass")) > MAX_SEGMENT for p in parts):
        return None
    parts = [p for p in parts if p]
    if not parts:
        parts = ["index.html"]
    try:
        base = root.resolve()
        candidate = (base.joinpath(*parts)).resolve()
        candidate.relative_to(base)
        return candidate if candidate.is_file() else None
    except (OSError, ValueError):  # ENAMETOOLONG, ELOOP, EACCES, ...; outside the root
        return None


def accepts_gzip(accept_encoding: Optional[str]) -> bool:
    """Whether an ``Accept-Encoding`` header value admits gzip (RFC 9110 §12.5.3): ``gzip``
    (or ``x-gzip``) with a non-zero q-value, or ``*`` with one when gzip is not named."""
    if not accept_encoding:
        return False
    named: Optional[float] = None
    star: Optional[float] = None
    for item in accept_encoding.split(","):
        token, _, params = item.strip().partition(";")
        token = token.strip().lower()
        q = 1.0
        for param in params.split(";"):
            key, _, value = param.strip().partition("=")
            if key.strip().lower() == "q":
                try:
                    q = float(value.strip())
                except ValueError:
                    q = 0.0
                if not 0.0 <= q <= 1.0:  # also NaN
                    q = 0.0
        if token in ("gzip", "x-gzip"):
            named = q if named is None else max(named, q)
        elif token == "*":
            star = q
    if named is not None:
        return named > 0.0
    return star is not None and star > 0.0


@dataclass(frozen=True)
class Asset:
    """One file of the page, as served: its bytes, their gzip copy (None when the file is not
    worth compressing or does not shrink), its content type and strong validator."""

    body: bytes
    gzipped: Optional[bytes]
    content_type: str
    etag: str
    compressible: bool


def _make_asset(path: Path, data: bytes) -> Asset:
    suffix = path.suffix.lower()
    compressible = suffix in COMPRESSIBLE
    gz = gzip.compress(data, compresslevel=GZIP_LEVEL, mtime=0) if compressible else None
    if gz is not None and len(gz) >= len(data):
        gz = None
    tag = hashlib.sha256(data).hexdigest()[:32]
    return Asset(data, gz, CONTENT_TYPES.get(suffix, "application/octet-stream"), tag, compressible)


class LabHandler(http.server.BaseHTTPRequestHandler):
    """Serves the files of ``server.root`` (see :func:`resolve_request`)."""

    server: LabServer
    server_version = "poinsot-lab"
    sys_version = ""

    def setup(self) -> None:
        super().setup()
        self.connection.settimeout(self.server.connection_timeout)  # every read and write
        # Every read of this connection is a read of the request head (HTTP/1.0: one request
        # per connection, and GET/HEAD have no body): all of them share one deadline.
        deadline = getattr(self.server._worker_local, "head_deadline", None)
        if deadline is None:  # not handed over by the gatekeeper: the deadline starts now
            deadline = time.monotonic() + self.server.connection_timeout
        self.rfile.close()  # the standard library's reader (it holds a reference to the socket)
        self.rfile = io.BufferedReader(
            _HeadReader(self.connection, deadline, self.server.connection_timeout)
        )

    def finish(self) -> None:
        try:
            super().finish()
        except OSError:  # the client went away, or timed out while we wrote
            pass

    def _allowed_host(self) -> bool:
        host = (self.headers.get("Host") or "").strip().lower()
        port = self.server.server_address[1]
        return host in {f"127.0.0.1:{port}", f"localhost:{port}", "127.0.0.1", "localhost"}

    def _common_headers(self) -> None:
        self.send_header("X-Content-Type-Options", "nosniff")
        self.send_header("Content-Security-Policy", CONTENT_SECURITY_POLICY)
        self.send_header("Cache-Control", "no-cache")

    def _send(self, status: int, body: bytes, content_type: str, head_only: bool) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self._common_headers()
        self.end_headers()
        if not head_only:
            self.wfile.write(body)

    def _not_found(self, head_only: bool) -> None:
        self._send(404, b"not found\n", "text/plain; charset=utf-8", head_only)

    def _serve(self, head_only: bool) -> None:
        if not self._allowed_host():
            self._not_found(head_only)
            return
        if len(self.path) > MAX_REQUEST_PATH:
            self._send(414, b"request path too long\n", "text/plain; charset=utf-8", head_only)
            return
        try:
            target = resolve_request(self.server.root, self.path)
        except (UnicodeDecodeError, ValueError):
            target = None
        if target is None:
            self._not_found(head_only)
            return
        try:
            asset = self.server.asset(target)
        except OSError:  # vanished or unreadable since it was resolved
            self._not_found(head_only)
            return
        if asset is None:
            self._stream(target, head_only)
            return
        use_gzip = asset.gzipped is not None and accepts_gzip(self.headers.get("Accept-Encoding"))
        etag = f'"{asset.etag}-gzip"' if use_gzip else f'"{asset.etag}"'
        inm = self.headers.get("If-None-Match")
        if inm is not None and (inm.strip() == "*" or etag in [t.strip() for t in inm.split(",")]):
            self.send_response(304)
            self.send_header("ETag", etag)
            if asset.compressible:
                self.send_header("Vary", "Accept-Encoding")
            self._common_headers()
            self.end_headers()
            return
        body = asset.gzipped if use_gzip and asset.gzipped is not None else asset.body
        self.send_response(200)
        self.send_header("Content-Type", asset.content_type)
        self.send_header("Content-Length", str(len(body)))
        if use_gzip:
            self.send_header("Content-Encoding", "gzip")
        if asset.compressible:
            self.send_header("Vary", "Accept-Encoding")
        self.send_header("ETag", etag)
        self._common_headers()
        self.end_headers()
        if not head_only:
            self.wfile.write(body)

    def _stream(self, target: Path, head_only: bool) -> None:
        """A file too large to keep in memory: sent as it is on disk, in chunks."""
        try:
            f = open(target, "rb")  # noqa: SIM115 (closed below)
        except OSError:
            self._not_found(head_only)
            return
        with f:
            size = os.fstat(f.fileno()).st_size
            self.send_response(200)
            self.send_header(
                "Content-Type", CONTENT_TYPES.get(target.suffix.lower(), "application/octet-stream")
            )
            self.send_header("Content-Length", str(size))
            self._common_headers()
            self.end_headers()
            if not head_only:
                shutil.copyfileobj(f, self.wfile, 1 << 16)

    def do_GET(self) -> None:
        self._serve(head_only=False)

    def do_HEAD(self) -> None:
        self._serve(head_only=True)

    def _refuse(self) -> None:
        self._send(405, b"method not allowed\n", "text/plain; charset=utf-8", head_only=False)

    do_POST = do_PUT = do_DELETE = do_PATCH = do_OPTIONS = _refuse  # noqa: N815

    def log_message(self, format: str, *args: Any) -> None:
        if self.server.verbose:
            super().log_message(format, *args)


class _HeadReader(io.RawIOBase):
    """The reads of a request head under one deadline (``time.monotonic()`` seconds): before
    it, a read waits at most until the deadline (and at most ``timeout`` s); at or past it, a
    read takes only what has arrived already and raises :class:`TimeoutError` when nothing has
    (a head that arrived in time but waited for a free worker is still read whole). The
    standard library's handler answers a :class:`TimeoutError` by closing the connection."""

    def __init__(self, sock: socket.socket, deadline: float, timeout: float) -> None:
        super().__init__()
        self._sock = sock
        self._deadline = deadline
        self._timeout = timeout

    def readable(self) -> bool:
        return True

    def readinto(self, buffer: Any) -> int:
        left = self._deadline - time.monotonic()
        self._sock.settimeout(min(max(left, 0.0), self._timeout))  # 0: do not wait at all
        try:
            return self._sock.recv_into(buffer)
        except (BlockingIOError, TimeoutError):
            raise TimeoutError("the request head did not arrive within its deadline") from None
        finally:
            self._sock.settimeout(self._timeout)  # the response's writes: per write


class LabServer(http.server.HTTPServer):
    """An HTTP server bound to the loopback interface, serving ``root``.

    A connection costs no thread until its request has arrived: accepted connections wait in a
    selector (at most ``max_pending`` of them, ``connection_timeout`` seconds each); a complete
    request goes to a worker thread, at most ``max_workers`` at once, whose reads and writes
    each time out after ``connection_timeout`` seconds; the whole request head must arrive
    within ``connection_timeout`` seconds of the connection's acceptance, one deadline across
    the selector's wait and the worker's reads (see the module's limits)."""

    allow_reuse_address = True
    request_queue_size = REQUEST_QUEUE_SIZE

    def __init__(
        self,
        root: Path,
        port: int = 0,
        *,
        host: str = LOOPBACK,
        verbose: bool = False,
        max_workers: int = MAX_WORKERS,
        max_pending: int = MAX_PENDING,
        connection_timeout: float = CONNECTION_TIMEOUT_S,
    ) -> None:
        if host != LOOPBACK:
            raise ValueError(f"host: the lab binds to {LOOPBACK} only, got {host!r}")
        if not 0 <= int(port) <= 65535:
            raise ValueError(f"port: must be in [0, 65535], got {port}")
        if not 1 <= int(max_workers) <= 1024:
            raise ValueError(f"max_workers: must be in [1, 1024], got {max_workers}")
        if not 1 <= int(max_pending) <= 65536:
            raise ValueError(f"max_pending: must be in [1, 65536], got {max_pending}")
        if not 0.0 < connection_timeout < float("inf"):
            raise ValueError(
                f"connection_timeout: must be finite and > 0 s, got {connection_timeout}"
            )
        self.root = Path(root).resolve()
        self.verbose = verbose
        self.max_workers = int(max_workers)
        self.max_pending = int(max_pending)
        self.connection_timeout = float(connection_timeout)
        self._slots = threading.BoundedSemaphore(self.max_workers)
        self._lock = threading.Lock()
        self._assets: dict[Path, tuple[int, int, Asset]] = {}
        self._incoming: list[tuple[socket.socket, Any, float]] = []
        self._worker_local = threading.local()  # .head_deadline of the worker's connection
        self._closing = threading.Event()
        super().__init__((host, int(port)), LabHandler)
        self._wake_r, self._wake_w = socket.socketpair()
        self._wake_r.setblocking(False)
        self._wake_w.setblocking(False)
        self._gate = threading.Thread(target=self._gatekeeper, name="poinsot-lab-gate", daemon=True)
        self._gate.start()

    @property
    def url(self) -> str:
        """The page's address, ``http://127.0.0.1:<port>/``."""
        return f"http://{LOOPBACK}:{self.server_address[1]}/"

    # ---- the files -------------------------------------------------------------------------

    def asset(self, path: Path) -> Optional[Asset]:
        """The served form of the regular file ``path`` (read and compressed once, again only
        when its size or modification time changes), or None for a file larger than
        :data:`MAX_CACHED_BYTES` (streamed instead)."""
        st = path.stat()
        if st.st_size > MAX_CACHED_BYTES:
            return None
        with self._lock:
            hit = self._assets.get(path)
        if hit is not None and hit[0] == st.st_mtime_ns and hit[1] == st.st_size:
            return hit[2]
        with open(path, "rb") as f:
            data = f.read(MAX_CACHED_BYTES + 1)
        if len(data) > MAX_CACHED_BYTES:  # grew since the stat
            return None
        made = _make_asset(path, data)
        with self._lock:
            self._assets[path] = (st.st_mtime_ns, st.st_size, made)
        return made

    # ---- the connections -------------------------------------------------------------------

    def process_request(self, request: Any, client_address: Any) -> None:
        """Called by ``serve_forever`` for each accepted connection: hands it to the
        gatekeeper, which waits (without a thread of its own) for its request to arrive."""
        with self._lock:
            self._incoming.append((request, client_address, time.monotonic()))
        self._wake()

    def _wake(self) -> None:
        try:
            self._wake_w.send(b"\0")
        except OSError:  # the wake-up pipe is full (it is woken already) or closed
            pass

    def _gatekeeper(self) -> None:
        """Watches the accepted connections until each has sent a whole request head (up to
        the blank line), then starts a worker for it; closes those that go quiet for
        ``connection_timeout`` s, that close, or that overflow ``max_pending``."""
        sel = selectors.DefaultSelector()
        sel.register(self._wake_r, selectors.EVENT_READ)
        pending: dict[socket.socket, tuple[Any, float]] = {}

        def drop(sock: socket.socket) -> None:
            sel.unregister(sock)
            del pending[sock]
            self.shutdown_request(sock)

        try:
            while not self._closing.is_set():
                with self._lock:
                    incoming, self._incoming = self._incoming, []
                for sock, address, since in incoming:
                    if len(pending) >= self.max_pending:  # the oldest waiting one makes room
                        drop(min(pending, key=lambda s: pending[s][1]))
                    try:
                        sock.setblocking(False)
                        sel.register(sock, selectors.EVENT_READ)
                    except (OSError, ValueError):  # closed already
                        self.shutdown_request(sock)
                        continue
                    pending[sock] = (address, since)
                for key, _ in sel.select(timeout=0.05):
                    if key.fileobj is self._wake_r:
                        try:
                            while self._wake_r.recv(4096):
                                pass
                        except OSError:
                            pass
                        continue
                    conn = cast(socket.socket, key.fileobj)
                    try:  # look at what has arrived, leaving it for the handler to read
                        head = conn.recv(MAX_REQUEST_HEAD, socket.MSG_PEEK)
                    except BlockingIOError:
                        continue
                    except OSError:
                        head = b""
                    if not head:  # the client closed (or reset) before sending a request
                        drop(conn)
                    elif b"\r\n\r\n" in head or b"\n\n" in head or len(head) >= MAX_REQUEST_HEAD:
                        address, since = pending[conn]
                        sel.unregister(conn)
                        del pending[conn]
                        self._start_worker(conn, address, since + self.connection_timeout)
                now = time.monotonic()
                for sock in [
                    s for s, (_, since) in pending.items() if now - since > self.connection_timeout
                ]:
                    drop(sock)
        finally:
            for sock in list(pending):
                drop(sock)
            sel.close()

    def _start_worker(self, sock: socket.socket, address: Any, head_deadline: float) -> None:
        # A free worker slot (workers never wait for a request, only on slow writes, which
        # time out): wait for one, unless the server is closing.
        while not self._slots.acquire(timeout=0.05):
            if self._closing.is_set():
                self.shutdown_request(sock)
                return
        sock.setblocking(True)
        try:
            threading.Thread(
                target=self._work,
                args=(sock, address, head_deadline),
                name="poinsot-lab-worker",
                daemon=True,
            ).start()
        except BaseException:
            self._slots.release()
            self.shutdown_request(sock)
            raise

    def _work(self, request: Any, client_address: Any, head_deadline: float) -> None:
        self._worker_local.head_deadline = head_deadline
        try:
            self.finish_request(request, client_address)
        except Exception:
            self.handle_error(request, client_address)
        finally:
            self.shutdown_request(request)
            self._slots.release()

    def handle_error(self, request: Any, client_address: Any) -> None:
        """A connection that failed (the client went away, a timeout, ...): one line when
        verbose, never a traceback."""
        if self.verbose:
            exc = sys.exc_info()[1]
            sys.stderr.write(
                f"poinsot lab: connection from {client_address[0]}:{client_address[1]} "
                f"ended: {type(exc).__name__}: {exc}\n"
            )

    def server_close(self) -> None:
        """Closes the listening socket and every connection still waiting for its request."""
        super().server_close()
        self._closing.set()
        self._wake()
        if self._gate is not threading.current_thread():
            self._gate.join(5.0)
        self._wake_r.close()
        self._wake_w.close()


def start_in_thread(root: Path, port: int = 0, **kwargs: Any) -> LabServer:
    """A :class:`LabServer` already serving from a daemon thread (tests, notebooks);
    ``kwargs`` go to :class:`LabServer`; stop it with ``server.shutdown(); server.server_close()``."""
    server = LabServer(root, port, **kwargs)
    threading.Thread(
        target=server.serve_forever, kwargs={"poll_interval": 0.05}, name="poinsot-lab", daemon=True
    ).start()
    return server
