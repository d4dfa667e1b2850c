#!/usr/bin/python3
"""Writes the seed corpora (corpus/<target>/) and the regression inputs of
known past bugs (regressions/<target>/) of the reader fuzz targets.

Run from anywhere with Debian's /usr/bin/python3 (its vtk module writes the
.vtp/.vtu seeds): the files are committed, this script documents and remakes
them. Shapes are tiny (a tetrahedron, a cube cut into 5 tets), so every seed
stays under a few KB; the repository's sample shapes are procedural and much
larger. The TetGen target reads one input as the .node file, the separator
"\\n@ele\\n" (fuzz_input.h), then the .ele file.
"""
import os
import shutil
import struct

import vtk

HERE = os.path.dirname(os.path.abspath(__file__))

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
CUBE_V = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_T = [(0, 1, 2, 4), (1, 3, 2, 7), (1, 2, 4, 7), (1, 5, 4, 7), (2, 4, 7, 6)]
SEPARATOR = b"\n@ele\n"


def put(kind, target, name, data):
    folder = os.path.join(HERE, kind, target)
    os.makedirs(folder, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def seed(target, name, data):
    put("corpus", target, name, data)


def regression(target, name, data):
    put("regressions", target, name, data)


def lines(rows):
    return "".join(" ".join(str(x) for x in row) + "\n" for row in rows)


def obj_seeds():
    seed("obj", "tetra.obj", lines(("v",) + v for v in TETRA_V) +
         lines(("f",) + tuple(i + 1 for i in f) for f in TETRA_F))
    seed("obj", "slashes_relative.obj",
         "# comment\no tetra\nv 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nv 0 0 1\n"
         "vt 0 0\nvn 0 0 1\ng side\nusemtl m\ns off\n"
         "f 1/1 3/1/1 2//1\nf -4 -3 -1\nf 1 4 3\nf 2 3 4\nl 1 2\n")
    regression("obj", "control_bytes_and_huge_token.obj",
               b"v 0 0 1\x1b[2J\x07" + b"9" * 3000 + b"x\n")
    regression("obj", "relative_before_first.obj", "v 0 0 0\nf 1 -2 1\n")
    regression("obj", "index_beyond_long_long.obj",
               "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n")


def off_seeds():
    seed("off", "tetra.off", "OFF\n4 4 6\n" + lines(TETRA_V) + lines((3,) + f for f in TETRA_F))
    seed("off", "coff_counts_on_header.off",
         "COFF 4 4 0 # colours\n" + lines(v + (255, 0, 0, 255) for v in TETRA_V) +
         lines((3,) + f + (0.5, 0.5, 0.5) for f in TETRA_F))
    regression("off", "vertex_count_2pow31.off", "OFF\n2147483647 0 0\n0 0 0\n")
    regression("off", "face_count_near_2pow31.off", "OFF 0 2147483000 0\n")
    regression("off", "count_beyond_int.off", "OFF\n2147483648 0 0\n")
    regression("off", "control_bytes_header.off", b"\x1b]0;owned\x07OFX\n")


def ply_header(encoding, vertex_type, vertex_count, face_count, extra=""):
    return ("ply\nformat %s 1.0\ncomment seed\nelement vertex %d\n"
            "property %s x\nproperty %s y\nproperty %s z\n%s"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n" %
            (encoding, vertex_count, vertex_type, vertex_type, vertex_type, extra, face_count))


def ply_seeds():
    seed("ply", "tetra_ascii.ply", ply_header("ascii", "float", 4, 4) + lines(TETRA_V) +
         lines((3,) + f for f in TETRA_F))
    for order, code in (("little", "<"), ("big", ">")):
        body = b"".join(struct.pack(code + "dddB", *v, 7) for v in TETRA_V)
        body += b"".join(struct.pack(code + "Biii", 3, *f) for f in TETRA_F)
        seed("ply", "tetra_binary_%s.ply" % order,
             ply_header("binary_%s_endian" % order, "double", 4, 4, "property uchar red\n")
             .encode() + body)
    floats = b"".join(struct.pack("<fff", *v) for v in TETRA_V)
    floats += b"".join(struct.pack("<Bfff", 3, *f) for f in TETRA_F)
    seed("ply", "float_indices.ply",
         ply_header("binary_little_endian", "float", 4, 4).replace(
             "uchar int vertex_indices", "uchar float vertex_indices").encode() + floats)
    twice = ("element vertex 40\nproperty double x\nproperty double y\nproperty double z\n"
             "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
             "end_header\n")
    regression("ply", "vertex_declared_twice_ascii.ply",
               "ply\nformat ascii 1.0\n" + twice + "1 2 3\n" * 43)
    regression("ply", "vertex_declared_twice_binary.ply",
               ("ply\nformat binary_little_endian 1.0\n" + twice).encode() +
               struct.pack("<ddd", 1, 2, 3) * 43)
    regression("ply", "vertex_count_2pow31.ply",
               "ply\nformat ascii 1.0\nelement vertex 2147483647\nproperty double x\n"
               "property double y\nproperty double z\nend_header\n0 0 0\n")
    regression("ply", "face_count_2pow31_binary.ply",
               ply_header("binary_little_endian", "float", 0, 2147483647).encode() + b"\x03")
    regression("ply", "list_length_nan.ply",
               ("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
                "property float y\nproperty float z\nproperty list float int extra\n"
                "end_header\n").encode() + struct.pack("<ffffii", 0, 0, 0, float("nan"), 1, 2))


def stl_seeds():
    facets = "".join("facet normal 0 0 0\nouter loop\n" +
                     "".join("vertex %g %g %g\n" % TETRA_V[i] for i in f) +
                     "endloop\nendfacet\n" for f in TETRA_F)
    seed("stl", "tetra_ascii.stl", "solid tetra\n" + facets + "endsolid tetra\n")
    binary = b"solid binary header".ljust(80, b" ") + struct.pack("<I", len(TETRA_F))
    for f in TETRA_F:
        binary += struct.pack("<3f", 0, 0, 0)
        for i in f:
            binary += struct.pack("<3f", *TETRA_V[i])
        binary += b"\0\0"
    seed("stl", "tetra_binary.stl", binary)


def vtk_points(vertices):
    points = vtk.vtkPoints()
    points.SetDataTypeToDouble()
    for v in vertices:
        points.InsertNextPoint(v)
    return points


def vtk_cells(rows):
    cells = vtk.vtkCellArray()
    for row in rows:
        cells.InsertNextCell(len(row), row)
    return cells


def vtk_variants(writer_class, data, target, stem):
    """The tetblend writer's own mode (appended raw zlib) and VTK's others."""
    modes = {
        "appended_zlib": lambda w: (w.SetDataModeToAppended(), w.EncodeAppendedDataOff(),
                                    w.SetCompressorTypeToZLib()),
        "appended_base64": lambda w: (w.SetDataModeToAppended(), w.EncodeAppendedDataOn(),
                                      w.SetCompressorTypeToNone()),
        "binary_inline": lambda w: (w.SetDataModeToBinary(), w.SetCompressorTypeToNone()),
        "ascii": lambda w: w.SetDataModeToAscii(),
    }
    paths = {}
    for mode, configure in modes.items():
        writer = writer_class()
        writer.SetInputData(data)
        configure(writer)
        path = os.path.join(HERE, "corpus", target, "%s_%s.%s" % (stem, mode, target))
        os.makedirs(os.path.dirname(path), exist_ok=True)
        writer.SetFileName(path)
        assert writer.Write() == 1
        paths[mode] = path
    return paths


def vtk_seeds():
    poly = vtk.vtkPolyData()
    poly.SetPoints(vtk_points(TETRA_V))
    poly.SetPolys(vtk_cells(TETRA_F))
    vtp = vtk_variants(vtk.vtkXMLPolyDataWriter, poly, "vtp", "tetra")
    grid = vtk.vtkUnstructuredGrid()
    grid.SetPoints(vtk_points(CUBE_V))
    grid.SetCells(vtk.VTK_TETRA, vtk_cells(CUBE_T))
    vtk_variants(vtk.vtkXMLUnstructuredGridWriter, grid, "vtu", "cube")
    # A compressed block header (UInt32 header_type: #blocks, block size,
    # last block size, compressed sizes) whose sizes were mutated: VTK
    # allocated gigabytes for the uncompressed block.
    data = open(vtp["appended_zlib"], "rb").read()
    start = data.index(b"<AppendedData encoding=\"raw\">")
    start = data.index(b"_", start) + 1
    mutated = data[:start] + struct.pack("<III", 1, 0x7ffffff0, 0x7ffffff0) + data[start + 12:]
    regression("vtp", "compressed_block_size_2pow31.vtp", mutated)


def tetgen_seeds():
    for base in (0, 1):
        node = "%d 3 0 0\n" % len(CUBE_V) + lines((i + base,) + v for i, v in enumerate(CUBE_V))
        ele = "%d 4 0\n" % len(CUBE_T) + lines(
            (i + base,) + tuple(x + base for x in t) for i, t in enumerate(CUBE_T))
        seed("tetgen", "cube_base%d" % base, node.encode() + SEPARATOR + ele.encode())
    node = "# points\n4 3 1 1\n" + lines((i,) + v + (0.5, 1) for i, v in enumerate(TETRA_V))
    ele = "1 4 1\n0 0 1 2 3 7\n"
    seed("tetgen", "tetra_attributes", node.encode() + SEPARATOR + ele.encode())
    regression("tetgen", "point_count_2pow31",
               b"2147483647 3 0 0\n0 0 0 0\n" + SEPARATOR + b"0 4 0\n")
    regression("tetgen", "tet_count_2pow31",
               b"4 3 0 0\n" + lines((i,) + v for i, v in enumerate(TETRA_V)).encode() +
               SEPARATOR + b"2147483647 4 0\n0 0 1 2 3\n")


def medit_seeds():
    text = ("MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n" % len(CUBE_V) +
            lines(v + (0,) for v in CUBE_V) +
            "Triangles\n1\n1 2 3 0\nEdges\n1\n1 2 0\nCorners\n1\n1\n" +
            "Tetrahedra\n%d\n" % len(CUBE_T) + lines(tuple(x + 1 for x in t) + (0,) for t in CUBE_T)
            + "End\n")
    seed("medit", "cube.mesh", text)
    regression("medit", "vertex_count_2pow31.mesh",
               "MeshVersionFormatted 1\nDimension 3\nVertices\n2147483647\n0 0 0 0\n")
    regression("medit", "tet_count_2pow31.mesh",
               "Dimension 3\nVertices 4\n" + lines(v + (0,) for v in TETRA_V) +
               "Tetrahedra 2147483647\n1 2 3 4 0\n")


def model_bytes(version, vertices, tets, triangles, surface_count, examples, names, excluded,
                counts=None, input_rows=(), cache=None):
    """A model file (pipeline/include/tetblend/pipeline/model_file.h); `counts` overrides the 5
    header counts; `cache` is the version 4 blend cache's payload bytes (cache_bytes)."""
    payload = struct.pack("<5Q", *(counts or (len(vertices), len(tets), len(triangles),
                                              surface_count, len(examples))))
    payload += b"".join(struct.pack("<3d", *v) for v in vertices)
    payload += b"".join(struct.pack("<4i", *t) for t in tets)
    payload += b"".join(struct.pack("<3i", *f) for f in triangles)
    for example in examples:
        payload += b"".join(struct.pack("<3d", *v) for v in example)
    for name in names:
        payload += struct.pack("<Q", len(name)) + name
    if version >= 2:
        payload += struct.pack("<Q", len(excluded)) + b"".join(struct.pack("<i", t) for t in excluded)
    if version >= 3:
        payload += struct.pack("<Q", len(input_rows)) + b"".join(
            struct.pack("<i", r) for r in input_rows)
    if version >= 4:
        payload += struct.pack("<Q", 0 if cache is None else 1) + (cache or b"")
    hash_ = 0xcbf29ce484222325
    # Version 4 on: FNV-1a's step over little-endian 64-bit words, then the tail bytes.
    words = len(payload) // 8 if version >= 4 else 0
    for (word,) in struct.iter_unpack("<Q", payload[:8 * words]):
        hash_ = ((hash_ ^ word) * 0x100000001b3) & 0xffffffffffffffff
    for byte in payload[8 * words:]:
        hash_ = ((hash_ ^ byte) * 0x100000001b3) & 0xffffffffffffffff
    return (b"TBMODEL\0" + struct.pack("<IQ", version, len(payload)) + payload +
            struct.pack("<Q", hash_))


def cache_bytes(unknowns, tets, examples):
    """A blend cache whose arrays have the right sizes: one supernode per unknown, no rows below,
    an identity factor; kaji parameters all zero."""
    def array(code, values):
        return struct.pack("<Q", len(values)) + b"".join(struct.pack("<" + code, v) for v in values)
    factor = (array("i", range(unknowns)) + array("i", range(unknowns + 1)) +
              array("i", [0] * (unknowns + 1)) + array("i", []) +
              array("q", range(unknowns + 1)) + array("d", [1.0] * unknowns))
    kaji = (struct.pack("<3Q", tets, examples, 1) + array("d", [0.0] * (9 * tets * examples)) +
            array("i", []) + array("i", [0]) + array("i", []) + array("d", []))
    return factor + kaji


def model_seeds():
    surface = [(0, 2, 1), (0, 1, 4), (0, 4, 2)]  # indices below the surface count
    stretched = [(2 * x, y, z) for x, y, z in CUBE_V]
    seed("model", "cube_v2.tbm", model_bytes(2, CUBE_V, CUBE_T, surface, 8, [stretched],
                                             [b"rest.obj", b"stretched.obj"], [1, 3]))
    # A seam: input vertices 8 and 9 are copies of surface vertices 1 and 2.
    seamed = [(0, 9, 8), (0, 1, 4), (0, 4, 2)]
    seed("model", "cube_v3_seam.tbm",
         model_bytes(3, CUBE_V, CUBE_T, seamed, 8, [stretched], [b"rest.obj", b"stretched.obj"],
                     [1], input_rows=list(range(8)) + [1, 2]))
    seed("model", "cube_v4_cache.tbm",
         model_bytes(4, CUBE_V, CUBE_T, surface, 8, [stretched], [b"rest.obj", b"stretched.obj"],
                     [], cache=cache_bytes(len(CUBE_V) - 1, len(CUBE_T), 1)))
    seed("model", "cube_v1.tbm", model_bytes(1, CUBE_V, CUBE_T, surface, 8, [],
                                             [b"rest.obj"], []))
    huge = (1 << 31) - 1
    for i, what in enumerate(("vertex", "tet", "triangle", "surface", "example")):
        counts = [len(CUBE_V), len(CUBE_T), len(surface), 8, 1]
        counts[i] = huge
        regression("model", "%s_count_2pow31.tbm" % what,
                   model_bytes(2, CUBE_V, CUBE_T, surface, 8, [stretched],
                               [b"rest.obj", b"stretched.obj"], [], counts))


def batch_seeds():
    shutil.copy(os.path.join(HERE, "..", "samples", "batch.json"),
                os.path.join(HERE, "corpus", "batch_spec", "samples_batch.json"))
    seed("batch_spec", "minimal.json", '{"model": "m.tbm", "jobs": [{"name": "a"}]}\n')
    seed("batch_spec", "every_field.json",
         '{"model": "/abs/m.tbm", "output_dir": "../out", "method": "dq", "consistency": "off",'
         ' "nonlinear": true, "surface_formats": ["obj", "ply"], "threads": 1024,'
         ' "jobs": [{"name": "a.b-c_d", "weights": [0.5, -1e300], "method": "linear"},'
         ' {"name": "e", "weights": "x"}]}\n')
    regression("batch_spec", "control_bytes_in_string.json", b'{"model": "a\x1b[2J\x07\n')
    regression("batch_spec", "threads_huge_object.json",
               '{"model": "m", "threads": {"a": [' + "1," * 2000 + '1]}, "jobs": [{"name": "a"}]}')


if __name__ == "__main__":
    # regressions/ also holds inputs the fuzzers found (kept as found): only
    # the corpus is remade from scratch.
    shutil.rmtree(os.path.join(HERE, "corpus"), ignore_errors=True)
    os.makedirs(os.path.join(HERE, "corpus", "batch_spec"))
    obj_seeds()
    off_seeds()
    ply_seeds()
    stl_seeds()
    vtk_seeds()
    tetgen_seeds()
    medit_seeds()
    model_seeds()
    batch_seeds()
