# SPDX-License-Identifier: LGPL-2.1-or-later
"""scripts/plot_map: the contact footprint of a sphere seen from above,
from the .vti maps the 3D boundary elements write beside each profile
(doc/sphere.md): the pressure p_hat = p/sigma_max in colour (compression
positive, the adhesive tension negative), the contact's edge (the gap at
1.2 eps) as a black line, x along the sliding direction (towards +x).

    scripts/plot_map OUT.png MAP.vti [MAP.vti ...]

Several maps go side by side with one colour scale, each titled with the
V_hat of its header. The nested grid's maps (.vtp, its points) are drawn
on their points, the band of divided cells outlined (grey, dashed): the
grid over the footprint."""
import re
import sys


def read_vti(path):
    """(x, y, fields, header) of an ASCII VTK image file as viscoslide
    writes it: x and y the point coordinates (in R), fields name -> 2D
    array (rows along y)."""
    import numpy as np
    text = open(path).read()
    extent = [int(v) for v in re.search(r'WholeExtent="([^"]*)"', text).group(1).split()]
    origin = [float(v) for v in re.search(r'Origin="([^"]*)"', text).group(1).split()]
    spacing = [float(v) for v in re.search(r'Spacing="([^"]*)"', text).group(1).split()]
    nx, ny = extent[1] + 1, extent[3] + 1
    fields = {}
    for name, data in re.findall(r'Name="([^"]+)"[^>]*>\s*([^<]*)</DataArray>', text):
        fields[name] = np.array(data.split(), dtype=float).reshape(ny, nx)
    x = origin[0] + spacing[0] * np.arange(nx)
    y = origin[1] + spacing[1] * np.arange(ny)
    header = re.search(r'<!--(.*?)-->', text)
    return x, y, fields, header.group(1).strip() if header else ''


def read_vtp(path):
    """(x, y, fields, header) of a VTK poly data file of points as the
    nested grid writes it (its arrays appended raw, each its UInt64 length
    in bytes then its values): x, y and each field one value per point."""
    import numpy as np
    data = open(path, 'rb').read()
    start = data.index(b'<AppendedData encoding="raw">')
    text = data[:start].decode()
    raw = data[data.index(b'_', start) + 1:]
    order = '<' if 'LittleEndian' in text else '>'

    def array(tag):
        offset = int(re.search(r'offset="(\d+)"', tag).group(1))
        size = int(np.frombuffer(raw, dtype=order + 'u8', count=1, offset=offset)[0])
        kind = np.dtype(order + {'Float32': 'f4', 'Float64': 'f8', 'Int32': 'i4',
                                 'Int64': 'i8'}[re.search(r'type="(\w+)"', tag).group(1)])
        values = np.frombuffer(raw, dtype=kind, count=size // kind.itemsize, offset=offset + 8)
        return values.astype(float)

    fields = {}
    for tag in re.findall(r'<DataArray[^>]*/>', text):
        name = re.search(r'Name="([^"]+)"', tag)
        if name:
            fields[name.group(1)] = array(tag)
    points = re.search(r'<Points>\s*(<DataArray[^>]*/>)', text).group(1)
    xyz = array(points).reshape(-1, 3)
    header = re.search(r'<!--(.*?)-->', text)
    return xyz[:, 0], xyz[:, 1], fields, header.group(1).strip() if header else ''


def draw(ax, x, y, f, norm):
    """One map on ax: the pressure in colour, the contact edge in black, a
    nested grid's fine points as dots."""
    if x.ndim == 1 and 'cell_over_eps' in f:
        image = ax.tripcolor(x, y, f['p_hat'], cmap='RdBu_r', norm=norm, shading='gouraud')
        ax.tricontour(x, y, f['gap_over_eps'], levels=[1.2], colors='k', linewidths=1.0)
        cell = f['cell_over_eps']
        ax.tricontour(x, y, cell, levels=[0.5 * (cell.min() + cell.max())],
                      colors='0.35', linewidths=0.6, linestyles='--')
        return image
    image = ax.pcolormesh(x, y, f['p_hat'], cmap='RdBu_r', norm=norm, shading='auto')
    ax.contour(x, y, f['gap_over_eps'], levels=[1.2], colors='k', linewidths=1.0)
    return image


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm
    out, paths = argv[0], argv[1:]
    maps = [read_vtp(p) if p.endswith('.vtp') else read_vti(p) for p in paths]
    low = min(m[2]['p_hat'].min() for m in maps)
    high = max(m[2]['p_hat'].max() for m in maps)
    norm = TwoSlopeNorm(vmin=min(low, -1e-3), vcenter=0., vmax=max(high, 1e-3))
    reach = max(max(abs(m[0]).max(), abs(m[1]).max()) for m in maps)
    fig, axes = plt.subplots(1, len(maps), figsize=(4.2 * len(maps), 4.4), squeeze=False)
    for ax, (x, y, f, header) in zip(axes[0], maps):
        image = draw(ax, x, y, f, norm)
        V = re.search(r'V_hat = (\S+?),', header)
        v = float(V.group(1)) if V else float('nan')
        ax.set_title(r'$\hat V = %s$' % (f'{v:.3g}' if v < 1e3 else f'{v:.0f}'))
        # beyond a smaller map the surface is free: zero pressure's colour
        ax.set_facecolor(plt.get_cmap('RdBu_r')(norm(0.)))
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
        ax.set_aspect('equal')
        ax.set_xlabel(r'$x/R$ (sliding towards $+x$)')
        ax.set_ylabel(r'$y/R$')
    fig.colorbar(image, ax=list(axes[0]), label=r'$p/\sigma_{max}$ (compression $> 0$)',
                 shrink=0.85)
    nested = any(m[0].ndim == 1 and 'cell_over_eps' in m[2] for m in maps)
    fig.suptitle('contact footprint; black: gap = 1.2 eps' +
                 ('; grey dashed: the band of divided cells' if nested else ''))
    fig.savefig(out, dpi=130, bbox_inches='tight')
    print(out)


if __name__ == '__main__':
    main(sys.argv[1:])
