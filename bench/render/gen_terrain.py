#!/usr/bin/env python3
"""Writes the render benchmark's terrain mesh (bench/README.md): a grid of N x N heights over
the square from -4 to 4 in x and z, two triangles a cell, as a binary PLY file for crtc and
the same vertices and faces as a POV-Ray mesh2 for POV-Ray.

usage: gen_terrain.py OUTDIR [N]      (default N = 708: 999,698 triangles)

The heights are computed from the grid index alone, so the files are the same on every
machine; the float values are written with 9 significant digits to the .inc, which reads
back as the very floats the PLY holds.
"""
import math
import os
import struct
import sys


def height(x, z):
    return (0.35 * math.sin(1.3 * x) * math.cos(0.9 * z) + 0.12 * math.sin(3.1 * x + 2.0 * z)
            + 0.05 * math.cos(7.0 * z - 5.0 * x))


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 708
    os.makedirs(out, exist_ok=True)
    vertices = []
    for j in range(n):
        for i in range(n):
            x = -4 + 8 * i / (n - 1)
            z = -4 + 8 * j / (n - 1)
            # Through float, as the PLY stores them, so both tools see the same numbers.
            vertices.append(tuple(struct.unpack('<3f', struct.pack('<3f', x, height(x, z), z))))
    faces = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b = j * n + i, j * n + i + 1
            c, d = a + n, b + n
            faces.append((a, c, b))
            faces.append((b, c, d))
    with open(os.path.join(out, 'terrain.ply'), 'wb') as f:
        f.write((f'ply\nformat binary_little_endian 1.0\ncomment crt render benchmark terrain\n'
                 f'element vertex {len(vertices)}\nproperty float x\nproperty float y\n'
                 f'property float z\nelement face {len(faces)}\n'
                 f'property list uchar int vertex_indices\nend_header\n').encode())
        f.write(b''.join(struct.pack('<3f', *v) for v in vertices))
        f.write(b''.join(struct.pack('<B3i', 3, *t) for t in faces))
    with open(os.path.join(out, 'terrain.inc'), 'w') as f:
        f.write('// crt render benchmark terrain: the same mesh as terrain.ply\n#declare Terrain = mesh2 {\n')
        f.write(f'  vertex_vectors {{ {len(vertices)},\n')
        f.write(',\n'.join('    <%.9g, %.9g, %.9g>' % v for v in vertices))
        f.write('\n  }\n')
        f.write(f'  face_indices {{ {len(faces)},\n')
        f.write(',\n'.join('    <%d, %d, %d>' % t for t in faces))
        f.write('\n  }\n}\n')


if __name__ == '__main__':
    main()
