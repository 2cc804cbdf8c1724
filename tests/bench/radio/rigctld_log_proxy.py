#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A logging TCP proxy for rigctld: what a radio controller sends, and when.

    rigctld_log_proxy.py --listen 4601 --to 127.0.0.1:4701 --log run.log

Listens on 127.0.0.1:LISTEN and relays every connection to rigctld at
HOST:PORT, byte for byte and at once (no line buffering on the path, so the
proxy adds well under a millisecond). Every complete line either way is
logged as

    <UTC ms since the epoch, 3 decimals> <connection> <direction> <line>

with `>` for the controller's command and `<` for rigctld's answer; the
time is the proxy's reading of the real-time clock when the line arrived.
A header line `# proxy ...` records the clocks at start. The log is what
tests/bench/radio/doppler_from_log reads.

The machine's real-time clock must not be stepped during a run; the
monotonic clock is logged beside it on the header for a check.
"""

import argparse
import asyncio
import socket
import sys
import time


class Log:
    def __init__(self, path):
        self.file = open(path, "a", buffering=1, encoding="utf-8", errors="replace")

    def line(self, conn, direction, text):
        t = time.time_ns() / 1e6
        self.file.write(f"{t:.3f} {conn} {direction} {text}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--listen", type=int, required=True, help="port to listen on (127.0.0.1)")
    parser.add_argument("--to", required=True, help="rigctld's HOST:PORT")
    parser.add_argument("--log", required=True, help="the log to append to")
    args = parser.parse_args()
    host, _, port = args.to.rpartition(":")
    log = Log(args.log)
    log.file.write(f"# proxy 127.0.0.1:{args.listen} -> {args.to}; utc_ms {time.time_ns() / 1e6:.3f} "
                   f"monotonic_ms {time.monotonic_ns() / 1e6:.3f}\n")
    count = 0

    async def pump(reader, writer, conn, direction):
        pending = b""
        try:
            while True:
                data = await reader.read(65536)
                if not data:
                    break
                writer.write(data)  # relayed first, logged after
                pending += data
                while b"\n" in pending:
                    raw, pending = pending.split(b"\n", 1)
                    log.line(conn, direction, raw.rstrip(b"\r").decode("latin-1"))
                await writer.drain()
        except (ConnectionError, OSError):
            pass
        finally:
            if pending:
                log.line(conn, direction, pending.decode("latin-1") + " [no newline]")
            log.line(conn, direction, "[closed]")
            writer.close()

    async def serve(client_reader, client_writer):
        nonlocal count
        count += 1
        conn = count
        try:
            radio_reader, radio_writer = await asyncio.open_connection(host, int(port))
        except OSError as e:
            log.line(conn, "!", f"[cannot reach rigctld: {e}]")
            client_writer.close()
            return
        for w in (client_writer, radio_writer):
            w.get_extra_info("socket").setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        log.line(conn, "!", f"[open from {client_writer.get_extra_info('peername')}]")
        await asyncio.gather(pump(client_reader, radio_writer, conn, ">"),
                             pump(radio_reader, client_writer, conn, "<"))

    async def run():
        server = await asyncio.start_server(serve, "127.0.0.1", args.listen)
        async with server:
            await server.serve_forever()

    try:
        asyncio.run(run())
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
