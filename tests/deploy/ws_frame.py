#!/usr/bin/env python3
"""Connects to a Geodesic daemon's /ws with a bearer token (standard library only), sends
nothing (the default scene streams), and waits for the first binary message: it must be a JPEG.
Prints the seconds it took and the JPEG's size; exits 1 otherwise.
  ws_frame.py HOST PORT TOKEN [TIMEOUT_SECONDS]"""
import base64, os, socket, struct, sys, time

host, port, token = sys.argv[1], int(sys.argv[2]), sys.argv[3]
timeout = float(sys.argv[4]) if len(sys.argv) > 4 else 120
start = time.monotonic()
sock = socket.create_connection((host, port), timeout=timeout)
key = base64.b64encode(os.urandom(16)).decode()
sock.sendall((f"GET /ws HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
              f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
              f"Authorization: Bearer {token}\r\n\r\n").encode())
buf = b""
while b"\r\n\r\n" not in buf:
    chunk = sock.recv(4096)
    if not chunk:
        sys.exit("ws: connection closed during the handshake")
    buf += chunk
head, buf = buf.split(b"\r\n\r\n", 1)
if not head.startswith(b"HTTP/1.1 101"):
    sys.exit("ws: no upgrade: " + head.split(b"\r\n")[0].decode(errors="replace"))


def read(n):
    global buf
    while len(buf) < n:
        chunk = sock.recv(65536)
        if not chunk:
            sys.exit("ws: connection closed")
        buf += chunk
    out, buf = buf[:n], buf[n:]
    return out


message, opcode = b"", 0
while time.monotonic() - start < timeout:
    b0, b1 = read(2)
    length = b1 & 0x7F
    if length == 126:
        length = struct.unpack(">H", read(2))[0]
    elif length == 127:
        length = struct.unpack(">Q", read(8))[0]
    payload = read(length)
    if b0 & 0x0F == 8:
        sys.exit("ws: the server closed the socket")
    if b0 & 0x0F in (1, 2):  # a new message; 0 continues a fragmented one
        message, opcode = b"", b0 & 0x0F
    message += payload
    if b0 & 0x80 and opcode == 2:  # the last fragment of a binary message
        if not (message.startswith(b"\xff\xd8\xff") and message.endswith(b"\xff\xd9")):
            sys.exit("ws: a binary message that is not a whole JPEG")
        print(f"ws: JPEG frame of {len(message)} bytes {time.monotonic() - start:.1f} s after connecting")
        sys.exit(0)
sys.exit(f"ws: no JPEG frame within {timeout} s")
