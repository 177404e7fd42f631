#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the seed X3P files of the fuzz corpus tests/fuzz/corpus/x3pReader/ (each a first
option byte, 'f' for fillInvalid or '-' for none, then the zip; tests/fuzz/ReaderChecks.hpp).
Tiny (8 x 8 points) valid files of each layout, so that the fuzzer starts past the checksums:
  d-binary.x3p      D binary data (x fastest), no CZ increment: heights in metres
  i-mask-fill.x3p   I binary data with CZ increment and offset, a valid-points mask with one
                    point masked out, filled
  l-binary.x3p      L binary data, stored (not deflated)
  f-nan.x3p         F binary data with one NaN point, not filled (an expected error)
  inline-fill.x3p   the data inline in Record3/DataList, one empty Datum, filled
and, for the reader's memory caps (issue 18, item 5), each a few kB:
  inline-markup.x3p     inline data with comments, a processing instruction, a <Datum/> and
                        attributes in Record3/DataList (read as main.xml inflates), filled
  header-small.x3p      inline-fill.x3p with main.xml's zip headers declaring 100 bytes (it
                        inflates to more: an expected error at the first byte beyond)
  header-huge.x3p       d-binary.x3p with main.xml's zip headers declaring 2^30 + 1 bytes, past
                        x3pLimits::maximumXmlBytes (refused before inflating)
  markup-bomb.x3p       d-binary.x3p with 4 MiB + 1 of whitespace in its markup, past
                        x3pLimits::maximumMarkupBytes (refused as it inflates)
Usage: tests/fuzz/makeX3pSeeds.py (from anywhere; rewrites the nine files)."""
import hashlib
import io
import math
import os
import struct
import zipfile

N = 8
here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "corpus", "x3pReader")


def main_xml(dtype, link, z_extra="", mask=None):
    axes = "".join(
        f"<{a}><AxisType>I</AxisType><DataType>D</DataType><Increment>{inc}</Increment>"
        f"<Offset>0</Offset></{a}>" for a, inc in (("CX", "1e-6"), ("CY", "2e-6")))
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">'
            f"<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>{axes}"
            f"<CZ><AxisType>A</AxisType><DataType>{dtype}</DataType>{z_extra}</CZ></Axes></Record1>"
            f"<Record2><Date>2026-01-01T00:00:00</Date></Record2>"
            f"<Record3><MatrixDimension><SizeX>{N}</SizeX><SizeY>{N}</SizeY><SizeZ>1</SizeZ>"
            f"</MatrixDimension>{link}</Record3></p:ISO5436_2>\n")


def data_link(data, mask=None):
    link = (f"<DataLink><PointDataLink>bin/data.bin</PointDataLink>"
            f"<MD5ChecksumPointData>{hashlib.md5(data).hexdigest().upper()}</MD5ChecksumPointData>")
    if mask is not None:
        link += (f"<ValidPointsLink>bin/valid.bin</ValidPointsLink>"
                 f"<MD5ChecksumValidPoints>{hashlib.md5(mask).hexdigest()}</MD5ChecksumValidPoints>")
    return link + "</DataLink>"


def archive(entries, store=False):
    buffer = io.BytesIO()
    method = zipfile.ZIP_STORED if store else zipfile.ZIP_DEFLATED
    with zipfile.ZipFile(buffer, "w", method) as z:
        for name, content in entries:
            info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))
            info.compress_type = method
            z.writestr(info, content)
    return buffer.getvalue()


def declare_size(content, entry, size):
    """The archive content with entry's inflated size in its local and central headers set to size."""
    b = bytearray(content)
    name = entry.encode()
    patched = 0
    for i in range(len(b) - 46):
        if b[i:i + 4] == b"PK\x03\x04" and b[i + 30:i + 30 + len(name)] == name:
            b[i + 22:i + 26] = struct.pack("<I", size)
            patched += 1
        elif b[i:i + 4] == b"PK\x01\x02" and b[i + 46:i + 46 + len(name)] == name:
            b[i + 24:i + 28] = struct.pack("<I", size)
            patched += 1
    assert patched == 2, entry
    return bytes(b)


def write(name, option, content):
    with open(os.path.join(out, name), "wb") as f:
        f.write(option + content)


heights = [1e-7 * math.sin(0.7 * i) for i in range(N * N)]
counts = [int(round(1000 * math.sin(0.7 * i))) for i in range(N * N)]

d = struct.pack(f"<{N * N}d", *heights)
d_binary = archive([("main.xml", main_xml("D", data_link(d))), ("bin/data.bin", d)])
write("d-binary.x3p", b"-", d_binary)
write("header-huge.x3p", b"-", declare_size(d_binary, "main.xml", (1 << 30) + 1))
bomb = main_xml("D", data_link(d)).replace("</Record3>", " " * ((4 << 20) + 1) + "</Record3>")
write("markup-bomb.x3p", b"-", archive([("main.xml", bomb), ("bin/data.bin", d)]))

i16 = struct.pack(f"<{N * N}h", *counts)
mask = bytearray(b"\xff" * (N * N // 8))
mask[2] &= ~(1 << 3)  # point 19 = (3, 2) invalid
mask = bytes(mask)
write("i-mask-fill.x3p", b"f",
      archive([("main.xml", main_xml("I", data_link(i16, mask), "<Increment>1e-10</Increment><Offset>1e-9</Offset>")),
               ("bin/data.bin", i16), ("bin/valid.bin", mask)]))

i32 = struct.pack(f"<{N * N}i", *[c * 1000 for c in counts])
write("l-binary.x3p", b"-",
      archive([("main.xml", main_xml("L", data_link(i32), "<Increment>1e-13</Increment>")), ("bin/data.bin", i32)],
              store=True))

f32 = struct.pack(f"<{N * N}f", *[h if i != 20 else float("nan") for i, h in enumerate(heights)])
write("f-nan.x3p", b"-", archive([("main.xml", main_xml("F", data_link(f32))), ("bin/data.bin", f32)]))

datums = "".join("<Datum></Datum>" if i == 9 else f"<Datum>{h!r}</Datum>" for i, h in enumerate(heights))
inline_fill = archive([("main.xml", main_xml("D", f"<DataList>{datums}</DataList>"))])
write("inline-fill.x3p", b"f", inline_fill)
write("header-small.x3p", b"f", declare_size(inline_fill, "main.xml", 100))
marked = "".join(
    "<!-- -- > --><?pi x?><Datum/>\n" if i == 9 else f'<Datum unit="m" >\n{h!r} </Datum >' for i, h in enumerate(heights))
write("inline-markup.x3p", b"f", archive([("main.xml", main_xml("D", f"<DataList >{marked}</DataList>"))]))
