"""The lab server (`poinsot lab`) under load: bytes over the wire for a page load, and the
latency of many parallel clients (issue 10, item 16). Not a test: it prints figures.

    python bench/lab_server_load.py                        # the built page of the package
    python bench/lab_server_load.py --page python/poinsot/lab --clients 200 --requests 15
    git show <rev>:python/poinsot/_labserver.py > /tmp/old_labserver.py
    python bench/lab_server_load.py --server-module /tmp/old_labserver.py   # another version
    python bench/lab_server_load.py --tricklers 40 --trickle-seconds 30   # issue 21, item 7

A page load is what a browser fetches: index.html and every file under assets/ (vite's output:
the script, the style sheet, the WebAssembly module), with a browser's Accept-Encoding; the
bytes counted are everything the server sends (status line, headers, body). A reload sends the
ETags back (If-None-Match), as a browser does for `Cache-Control: no-cache`.

With --tricklers N, N connections each send a 64 KiB request head without its blank line, then
one byte every 4 s (each read of the server well inside its 10 s timeout), for
--trickle-seconds; meanwhile one normal client fetches index.html every 0.5 s, and the figures
are its latencies and how long the server kept the tricklers open.
"""

from __future__ import annotations

import argparse
import importlib.util
import re
import socket
import statistics
import sys
import threading
import time
from pathlib import Path
from types import ModuleType

BROWSER_ACCEPT_ENCODING = "gzip, deflate, br, zstd"


def load_server_module(path: str | None) -> ModuleType:
    if path is None:
        from poinsot import _labserver

        return _labserver
    spec = importlib.util.spec_from_file_location("labserver_under_test", path)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod  # dataclasses look their module up there
    spec.loader.exec_module(mod)
    return mod


def fetch(port: int, path: str, extra: str = "", timeout: float = 300.0) -> tuple[int, bytes, bytes]:
    """One HTTP/1.0 GET on a fresh connection: status, raw headers, body (the server closes)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(f"GET {path} HTTP/1.0\r\nHost: 127.0.0.1:{port}\r\nAccept-Encoding: "
                  f"{BROWSER_ACCEPT_ENCODING}\r\n{extra}\r\n".encode())
        chunks = []
        while True:
            chunk = s.recv(1 << 16)
            if not chunk:
                break
            chunks.append(chunk)
    raw = b"".join(chunks)
    head, _, body = raw.partition(b"\r\n\r\n")
    return int(head.split(b" ", 2)[1]), head, body


def page_files(page: Path) -> list[str]:
    return ["/"] + sorted("/" + p.relative_to(page).as_posix() for p in (page / "assets").rglob("*") if p.is_file())


def page_load(port: int, files: list[str]) -> tuple[int, int, dict[str, str]]:
    """Bytes over the wire for a first load and for a reload with the ETags sent back."""
    first, etags = 0, {}
    for f in files:
        status, head, body = fetch(port, f)
        assert status == 200, (f, status)
        first += len(head) + 4 + len(body)
        m = re.search(rb"(?im)^etag:\s*(.+?)\s*$", head)
        if m:
            etags[f] = m.group(1).decode()
    reload = 0
    for f in files:
        extra = f"If-None-Match: {etags[f]}\r\n" if f in etags else ""
        status, head, body = fetch(port, f, extra)
        assert status in (200, 304), (f, status)
        reload += len(head) + 4 + len(body)
    return first, reload, etags


def parallel(port: int, files: list[str], clients: int, requests: int) -> tuple[list[float], int, float]:
    """`clients` threads, started together, each making `requests` requests in turn through
    the page's files; the latency of every request (s), the failures, the wall time."""
    latencies: list[float] = []
    failures = [0]
    lock = threading.Lock()
    barrier = threading.Barrier(clients + 1)

    def client(k: int) -> None:
        barrier.wait()
        for i in range(requests):
            path = files[(k + i) % len(files)]
            t0 = time.perf_counter()
            try:
                ok = fetch(port, path)[0] == 200
            except OSError:
                ok = False
            dt = time.perf_counter() - t0
            with lock:
                latencies.append(dt)
                failures[0] += not ok

    threads = [threading.Thread(target=client, args=(k,), daemon=True) for k in range(clients)]
    for t in threads:
        t.start()
    barrier.wait()
    t0 = time.perf_counter()
    for t in threads:
        t.join()
    return latencies, failures[0], time.perf_counter() - t0


def trickled(port: int, tricklers: int, seconds: float, period: float = 4.0) -> None:
    """`tricklers` slow-head connections against one normal client, for `seconds` s."""
    pad = "".join(f"X-Pad-{i:02d}: {'a' * 1020}\r\n" for i in range(64))
    head = f"GET / HTTP/1.0\r\nHost: 127.0.0.1:{port}\r\n{pad}X-Slow: ".encode()
    stop = threading.Event()
    held: list[float] = []
    lock = threading.Lock()

    def trickle() -> None:
        t0 = time.perf_counter()
        with socket.create_connection(("127.0.0.1", port), timeout=30) as s:
            s.sendall(head)
            s.settimeout(period)
            while not stop.is_set():
                try:
                    if s.recv(1024) == b"":
                        break
                except (TimeoutError, socket.timeout):
                    pass
                except OSError:
                    break
                try:
                    s.sendall(b"a")
                except OSError:
                    break
        with lock:
            held.append(time.perf_counter() - t0)

    threads = [threading.Thread(target=trickle, daemon=True) for _ in range(tricklers)]
    for t in threads:
        t.start()
    time.sleep(1.0)
    latencies, failed = [], 0
    t_end = time.perf_counter() + seconds
    while time.perf_counter() < t_end:
        t0 = time.perf_counter()
        try:
            ok = fetch(port, "/", timeout=max(1.0, t_end - t0))[0] == 200
        except OSError:
            ok = False
        latencies.append(time.perf_counter() - t0)
        failed += not ok
        time.sleep(0.5)
    stop.set()
    for t in threads:
        t.join(period + 5)
    print(f"{tricklers} tricklers (64 KiB head, then 1 byte / {period:g} s) for {seconds:g} s: "
          f"normal client {len(latencies)} requests, {failed} failed, max latency {max(latencies):.2f} s, "
          f"median {statistics.median(latencies) * 1e3:.1f} ms; tricklers held open: "
          f"max {max(held):.1f} s (closed by the server: {sum(h < seconds for h in held)})")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--page", type=Path, default=None, help="built page directory (default: the package's)")
    ap.add_argument("--server-module", default=None, help="a _labserver.py to load instead of poinsot's")
    ap.add_argument("--clients", type=int, default=200)
    ap.add_argument("--requests", type=int, default=15, help="requests per client")
    ap.add_argument("--tricklers", type=int, default=0, help="slow-head connections (0: skip)")
    ap.add_argument("--trickle-seconds", type=float, default=30.0)
    args = ap.parse_args()

    mod = load_server_module(args.server_module)
    page = (args.page or mod.page_dir()).resolve()
    if not (page / "index.html").is_file():
        print(f"no built page at {page}: run `make lab-build` (or `bash web/build.sh`)", file=sys.stderr)
        return 1
    srv = mod.start_in_thread(page)
    port = srv.server_address[1]
    try:
        files = page_files(page)
        size = sum((page / f.lstrip("/")).stat().st_size if f != "/" else (page / "index.html").stat().st_size
                   for f in files)
        first, reload, etags = page_load(port, files)
        print(f"server: {mod.__file__}")
        print(f"page: {len(files)} files, {size} bytes on disk")
        print(f"page load, bytes over the wire: first {first}, reload {reload} "
              f"({'ETags' if etags else 'no ETags'})")
        if args.tricklers:
            trickled(port, args.tricklers, args.trickle_seconds)
            return 0
        lat, failed, wall = parallel(port, files, args.clients, args.requests)
        lat.sort()
        n = len(lat)

        def pct(p: float) -> float:
            return lat[min(n - 1, int(p * n))]

        print(f"{args.clients} parallel clients x {args.requests} requests = {n} requests in {wall:.2f} s, "
              f"{failed} failed")
        print(f"latency: median {statistics.median(lat) * 1e3:.1f} ms, p99 {pct(0.99) * 1e3:.1f} ms, "
              f"max {lat[-1]:.2f} s; over 1 s: {sum(x > 1 for x in lat)}, over 30 s: {sum(x > 30 for x in lat)}")
    finally:
        srv.shutdown()
        srv.server_close()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
