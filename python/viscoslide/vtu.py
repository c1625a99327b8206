# SPDX-License-Identifier: LGPL-2.1-or-later
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


def cell_shape(pvtu):
    """'hexahedra' (a 3D volume), 'quadrilaterals' (a 2D volume or a 3D
    surface) or 'lines' (a 2D surface): the cells of the first piece."""
    with open(pvtu) as f:
        piece = re.search(r'<Piece Source="([^"]+)"', f.read()).group(1)
    offsets = read_vtu(os.path.join(os.path.dirname(pvtu), piece))['offsets']
    return {8: 'hexahedra', 4: 'quadrilaterals'}.get(offsets[0], 'lines')


# The faces of a VTK hexahedron, each in cyclic order.
HEX_FACES = ((0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))


def read_pvtu_slice(pvtu, field, axis=1, at=0.):
    """A plane of a 3D .pvtu: the faces of its hexahedra that lie on
    coordinate `axis` = `at` (a plane of the mesh's faces, such as y = 0,
    the track's centre line), each once: the in-plane points (the two other
    coordinates in order), the field's values there and the triangles."""
    with open(pvtu) as f:
        pieces = re.findall(r'<Piece Source="([^"]+)"', f.read())
    inplane = [d for d in range(3) if d != axis]
    a, b, v, tris = [], [], [], []
    for piece in pieces:
        d = read_vtu(os.path.join(os.path.dirname(pvtu), piece))
        if field not in d:
            sys.exit(f'no field {field} in {piece}')
        p, values = d['points'], d[field]
        conn, offsets = d['connectivity'], d['offsets']
        scale = max(abs(c) for c in p) or 1.
        index = {}  # piece's point -> slice's point

        def point(i):
            if i not in index:
                index[i] = len(a)
                a.append(p[3 * i + inplane[0]])
                b.append(p[3 * i + inplane[1]])
                v.append(values[i])
            return index[i]
        start = 0
        for end in offsets:
            cell = conn[start:end]
            start = end
            if len(cell) != 8:
                continue
            on = [abs(p[3 * i + axis] - at) < 1e-9 * scale for i in cell]
            # the face on the plane, of the cell on its upper side only
            if sum(on) != 4 or any(p[3 * i + axis] < at for i in cell):
                continue
            face = next(f for f in HEX_FACES if all(on[k] for k in f))
            q = [point(cell[k]) for k in face]
            tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    if not tris:
        sys.exit(f'{pvtu}: no cell faces on the plane of coordinate {axis} = {at}')
    return a, b, v, tris


def triangle_integrals(x, y, v, tris):
    """Per written triangle: its integral of the field (area times the mean
    of its corners' values, exact for the field linear on it) and its
    centroid (x, y); what the checks sum over regions."""
    for a, b, c in tris:
        area = abs((x[b] - x[a]) * (y[c] - y[a]) - (x[c] - x[a]) * (y[b] - y[a])) / 2
        yield area * (v[a] + v[b] + v[c]) / 3, (x[a] + x[b] + x[c]) / 3, (y[a] + y[b] + y[c]) / 3
