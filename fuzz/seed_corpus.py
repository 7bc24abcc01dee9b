#!/usr/bin/env python3
"""Writes a few hand-made seed inputs into fuzz/corpus (run once; libFuzzer adds what it finds)."""
import os, struct, zlib

here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
os.makedirs(here, exist_ok=True)

def packet(op, payload=b"", seq=0, ack=0, mask=0, version=1):
    body = bytes([0x4E, op, version, 1 if seq else 0]) + struct.pack("<HHH", seq, ack, mask) + payload
    tele = body + struct.pack("<I", zlib.crc32(body) & 0xFFFFFFFF)
    return struct.pack("<H", len(tele)) + tele

hello = packet(0x01, bytes([1]) + struct.pack("<I", 0xC0FFEE) + b"\x01")
seeds = {
    "hello": hello,
    "hello_explore_stop": hello + packet(0x02, seq=1) + packet(0x03, seq=2) + packet(0x02, seq=2),
    "path": hello + packet(0x04, struct.pack("<HHhh", 7, 5, 0, 0) + bytes([0x10, 0x32]), seq=1),
    "chunk": hello + packet(0x06, struct.pack("<HHHhhhhHH", 1, 0, 1, -2, -2, 5, 5, 0, 8) + bytes([0x55, 0x9A]), seq=1),
    "request_map_ack": hello + packet(0x05, seq=1) + packet(0x07, ack=3, mask=3),
    "lego": bytes([2, 0, 0x00, 0x0B, 2, 0, 0x00, 0x0D, 7, 0, 0x00, 0x09, 3, 3, ord('h'), ord('i'), 0,
                   5, 0, 0x00, 0x13, 13, 0, 1]),
    "delta": packet(0x43, struct.pack("<HBhhhhB", 2, 0x66, -3, -3, 10, 10, 1) + struct.pack("<HB", 4100, 5) + bytes([0x59, 0x02]), seq=9),
    "status": packet(0x42, bytes([1]) + struct.pack("<hhB", 1, 2, 1) + struct.pack("<HHH", 7800, 1, 0) +
                     struct.pack("<HHBhh", 1, 2, 3, 4, 5)),
}
for name, data in seeds.items():
    with open(os.path.join(here, "seed-" + name), "wb") as f:
        f.write(data)
print("wrote", len(seeds), "seeds to", here)
