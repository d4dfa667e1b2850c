"""The ASCII OFF reader the rehearsal tools share (Python standard library only)."""


def read_off(path):
    """Vertex rows and triangles of an ASCII OFF file. A vertex row is its
    line's first three numbers as text (written back, they are the file's
    values exactly; comments, C/N/ST prefixes and per-vertex colours
    allowed); polygons are fanned from their first corner."""
    with open(path) as f:
        rows = [line.split("#", 1)[0].split() for line in f]
    rows = [row for row in rows if row]
    if not rows[0][0].endswith("OFF"):
        raise SystemExit(f"{path}: not an OFF file")
    header, first = (rows[0][1:], 1) if len(rows[0]) > 1 else (rows[1], 2)
    vertex_count, face_count = int(header[0]), int(header[1])
    vertices = [row[:3] for row in rows[first:first + vertex_count]]
    triangles = []
    for row in rows[first + vertex_count:first + vertex_count + face_count]:
        corners = [int(x) for x in row[1:1 + int(row[0])]]
        for j in range(1, len(corners) - 1):
            triangles.append((corners[0], corners[j], corners[j + 1]))
    return vertices, triangles


def read_off_positions(path):
    """Vertex positions (float triples) and triangles of an ASCII OFF file."""
    rows, triangles = read_off(path)
    return [tuple(map(float, row)) for row in rows], triangles


def write_off(path, vertices, triangles):
    """Writes an ASCII OFF file: each vertex row's coordinates as given when
    they are text (read_off's rows, written back exactly), else with 17
    significant digits; the triangles as they are."""
    def text(x):
        return x if isinstance(x, str) else "%.17g" % x
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(triangles)} 0\n")
        f.writelines(" ".join(text(x) for x in vertex) + "\n" for vertex in vertices)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in triangles)
