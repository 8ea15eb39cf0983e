"""A small PNG decoder (zlib only), for comparing the CLI's images with the
module's arrays: 8-bit grey, RGB, grey+alpha, RGBA and palette images (bit
depths 1..8 for grey and palette), not interlaced. Debian has no PIL by default.
"""
import struct
import zlib

import numpy as np

CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}


def _chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos = 8
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + length]
        if zlib.crc32(kind + body) != struct.unpack(">I", data[pos + 8 + length : pos + 12 + length])[0]:
            raise ValueError(f"bad CRC in {kind!r}")
        yield kind, body
        pos += 12 + length


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def _unfilter(raw, height, stride, bpp):
    out = bytearray(height * stride)
    prev = bytearray(stride)
    pos = 0
    for y in range(height):
        kind = raw[pos]
        line = bytearray(raw[pos + 1 : pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + ((a + b) >> 1)) & 255
            elif kind == 4:
                line[i] = (line[i] + _paeth(a, b, c)) & 255
            elif kind != 0:
                raise ValueError(f"bad filter {kind}")
        out[y * stride : (y + 1) * stride] = line
        prev = line
    return out


def read_png(path):
    """The pixels as a uint8 array [H, W] (one channel) or [H, W, C], top row
    first; a palette image gives its colours ([H, W, 3])."""
    with open(path, "rb") as f:
        data = f.read()
    idat = b""
    palette = None
    for kind, body in _chunks(data):
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            palette = np.frombuffer(body, dtype=np.uint8).reshape(-1, 3)
        elif kind == b"IDAT":
            idat += body
    if interlace != 0 or (depth != 8 and colour not in (0, 3)) or depth > 8:
        raise ValueError("unsupported PNG")
    channels = CHANNELS[colour]
    stride = (width * channels * depth + 7) // 8
    rows = _unfilter(zlib.decompress(idat), height, stride, max(1, channels * depth // 8))
    packed = np.frombuffer(bytes(rows), dtype=np.uint8).reshape(height, stride)
    if depth < 8:
        bits = np.unpackbits(packed, axis=1).reshape(height, -1, depth)[:, :width]
        weights = 1 << np.arange(depth - 1, -1, -1)
        pixels = (bits * weights).sum(axis=2).astype(np.uint8)
        if colour == 0:
            pixels = (pixels * (255 // ((1 << depth) - 1))).astype(np.uint8)
    else:
        pixels = packed.reshape(height, width, channels)
        if channels == 1:
            pixels = pixels[:, :, 0]
    if colour == 3:
        return palette[pixels]
    return pixels
