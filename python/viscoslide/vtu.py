"""A reader of the VTU/PVTU fields viscoslide writes, standard library only.

deal.II writes binary DataArrays, base64-encoded and zlib-compressed in
blocks; this reads them without VTK so that the tests (Fig. 5's
dissipation maps, tests/figure_sweep.check) can integrate a field, and
viscoslide.plot_field draws one."""
import base64
import os
import re
import struct
import sys
import zlib


TYPES = {'Float32': 'f', 'Float64': 'd', 'Int32': 'i', 'Int64': 'q', 'UInt8': 'B',
         'UInt32': 'I', 'UInt64': 'Q'}


def decode(text, vtype, compressed):
    """A binary DataArray: base64 header (UInt32) and base64 data."""
    text = ''.join(text.split())
    if not compressed:
        raw = base64.b64decode(text)
        n = struct.unpack('<I', raw[:4])[0]
        raw = raw[4:4 + n]
    else:
        first = base64.b64decode(text[:8])  # the block count
        nblocks = struct.unpack('<I', first[:4])[0]
        hlen = 4 * ((4 * (3 + nblocks) + 2) // 3)
        header = struct.unpack(f'<{3 + nblocks}I', base64.b64decode(text[:hlen]))
        data = base64.b64decode(text[hlen:])
        raw, pos = b'', 0
        for size in header[3:]:
            raw += zlib.decompress(data[pos:pos + size])
            pos += size
    code = TYPES[vtype]
    return struct.unpack(f'<{len(raw) // struct.calcsize(code)}{code}', raw)


def read_vtu(path):
    with open(path) as f:
        xml = f.read()
    compressed = 'vtkZLibDataCompressor' in xml
    arrays = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', xml, re.S):
        attrs, body = m.group(1), m.group(2)
        vtype = re.search(r'type="(\w+)"', attrs).group(1)
        name = re.search(r'Name="([^"]+)"', attrs)
        name = name.group(1) if name else 'points'
        arrays[name] = decode(body, vtype, compressed)
    return arrays


def read_pvtu(pvtu, field):
    """Points (x, y), the field's values and the triangles of all pieces."""
    with open(pvtu) as f:
        pieces = re.findall(r'<Piece Source="([^"]+)"', f.read())
    x, y, v, tris = [], [], [], []
    for piece in pieces:
        d = read_vtu(os.path.join(os.path.dirname(pvtu), piece))
        if field not in d:
            sys.exit(f'scripts/plot_field: no field {field} in {piece}')
        base = len(x)
        p = d['points']
        x += p[0::3]
        y += p[1::3]
        v += d[field]
        conn, offsets = d['connectivity'], d['offsets']
        start = 0
        for end in offsets:  # quadrilaterals, split into two triangles
            q = [base + i for i in conn[start:end]]
            if len(q) == 4:
                tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
            start = end
    return x, y, v, tris


def triangle_integrals(x, y, v, tris):
    """Per written triangle: its integral of the field (area times the mean
    of its corners' values, exact for the field linear on it) and its
    centroid (x, y); what the checks sum over regions."""
    for a, b, c in tris:
        area = abs((x[b] - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (y[b] - y[a])) / 2
        yield area * (v[a] + v[b] + v[c]) / 3, (x[a] + x[b] + x[c]) / 3, (y[a] + y[b] + y[c]) / 3
