"""An 8-bit RGB PNG writer for the scripts that make Prism's test textures (standard library only)."""
import struct, zlib

def png(path, w, h, pixel):
    """Writes a w × h PNG whose pixel(x, y) is an (r, g, b) tuple of 0–255 ints, row 0 at the top."""
    rows = b"".join(b"\0" + bytes(c for x in range(w) for c in pixel(x, y)) for y in range(h))
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    data += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(data)
