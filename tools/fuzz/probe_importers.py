#!/usr/bin/env python3
"""Probes assimp's readers through `mhd validate` with mutated small files.

libFuzzer's target (mhd-fuzz-mesh-header) names its input .ply, .obj or .stl only, and
sees no coverage inside assimp. This probe sweeps more of the formats a scene may name
(fourteen, PLY and STL in text and binary): for each run it takes a small valid file of
one format, changes a few bytes (flips, cuts, repeats, and inserts such as 0, -1, NaN or
a huge count), and runs `mhd validate` on a scene of that one mesh. A run must end with
exit status 0 or 1 within the timeout; a signal, another status or a timeout is kept,
once per kind, as a file in --out. First, each seed as it is must load (exit status 2
if one does not).

    tools/fuzz/probe_importers.py [--mhd PATH] [--seconds S] [--seed N] [--out DIR] [--formats .3ds,...]

docs/reliability/fuzzing.md gives what it found.
"""
import argparse
import collections
import os
import random
import struct
import subprocess
import sys
import time

SEEDS = {
    ".off": b"OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n4 0 1 2 3\n",
    ".obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 3 4\n",
    ".stl": b"solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
            b"endloop\nendfacet\nendsolid a\n",
    ".gltf": b'{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],'
             b'"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],'
             b'"buffers":[{"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAA'
             b'AAAAAAAAgD8AAAAAAAABAAIAAAA=","byteLength":44}],"bufferViews":[{"buffer":0,"byteLength":36},'
             b'{"buffer":0,"byteOffset":36,"byteLength":6}],"accessors":[{"bufferView":0,"componentType":5126,'
             b'"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]},{"bufferView":1,"componentType":5123,'
             b'"count":3,"type":"SCALAR"}]}',
    ".dae": b'<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" '
            b'version="1.4.1"><library_geometries><geometry id="g"><mesh><source id="p">'
            b'<float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array><technique_common>'
            b'<accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>'
            b'<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>'
            b'</source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices>'
            b'<triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p>'
            b'</triangles></mesh></geometry></library_geometries><library_visual_scenes>'
            b'<visual_scene id="s"><node><instance_geometry url="#g"/></node></visual_scene>'
            b'</library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>',
    ".ply": b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            b"property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
            b"0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n4 0 1 2 3\n",
    ".ac": b'AC3Db\nMATERIAL "" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0.5 0.5 0.5  shi 10  trans 0\n'
           b'OBJECT world\nkids 1\nOBJECT poly\nname "a"\nnumvert 3\n0 0 0\n1 0 0\n0 1 0\nnumsurf 1\n'
           b"SURF 0x10\nmat 0\nrefs 3\n0 0 0\n1 0 0\n2 0 0\nkids 0\n",
    ".x": b"xof 0303txt 0032\nMesh {\n3;\n0;0;0;,\n1;0;0;,\n0;1;0;;\n1;\n3;0,1,2;;\n}\n",
    ".smd": b'version 1\nnodes\n0 "root" -1\nend\nskeleton\ntime 0\n0 0 0 0 0 0 0\nend\ntriangles\nmat\n'
            b"0 0 0 0 0 0 1 0 0\n0 1 0 0 0 0 1 0 0\n0 0 1 0 0 0 1 0 0\nend\n",
    ".nff": b"pp 3\n0 0 0\n1 0 0\n0 1 0\n",
    ".raw": b"0 0 0 1 0 0 0 1 0\n",
}


def _chunk_3ds(chunk_id, body):
    return struct.pack("<HI", chunk_id, 6 + len(body)) + body


def _three_ds():
    """One triangle in 3DS chunks: main, version, editor, object "a", its mesh's vertices and face."""
    vertices = struct.pack("<H9f", 3, 0, 0, 0, 1, 0, 0, 0, 1, 0)
    faces = struct.pack("<H4H", 1, 0, 1, 2, 0)
    mesh = _chunk_3ds(0x4100, _chunk_3ds(0x4110, vertices) + _chunk_3ds(0x4120, faces))
    editor = _chunk_3ds(0x3D3D, _chunk_3ds(0x4000, b"a\0" + mesh))
    return _chunk_3ds(0x4D4D, _chunk_3ds(0x0002, struct.pack("<I", 3)) + editor)


def _glb():
    """The .gltf seed's triangle as binary glTF: a JSON chunk and a BIN chunk."""
    js = (b'{"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],'
          b'"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"buffers":[{"byteLength":44}],'
          b'"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],'
          b'"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],'
          b'"min":[0,0,0]},{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]}')
    js += b" " * (-len(js) % 4)
    data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2) + b"\0\0"
    body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(data), b"BIN\0") + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def _binary_stl():
    tri = struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0)
    return b"binary".ljust(80, b" ") + struct.pack("<I", 2) + tri + tri


# Seeds built in binary: 3DS, binary glTF, and binary PLY and STL, whose headers MHD
# reads itself; and FBX.
MORE_SEEDS = [
    (".3ds", _three_ds()),
    (".glb", _glb()),
    (".fbx", b'; FBX 7.4.0 project file\nFBXHeaderExtension: {\nFBXHeaderVersion: 1003\nFBXVersion: 7400\n}\n'
             b'Objects: {\nGeometry: 1, "Geometry::", "Mesh" {\nVertices: *12 {\na: 0,0,0,1,0,0,0,1,0,0,0,1\n}\n'
             b'PolygonVertexIndex: *7 {\na: 0,1,-3,0,1,2,-4\n}\nGeometryVersion: 124\n}\n'
             b'Model: 2, "Model::a", "Mesh" {\nVersion: 232\n}\n}\nConnections: {\nC: "OO",1,2\nC: "OO",2,0\n}\n'),
    (".ply", b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
             b"property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n" +
             struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1) + struct.pack("<B3i", 3, 0, 1, 2) +
             struct.pack("<B4i", 4, 0, 1, 2, 3)),
    (".stl", _binary_stl()),
]
INSERTS = [b"0", b"-1", b" 0 ", b"999999", b"\n", b"3 0 0 0", b"\x00", b"\xff\xff\xff\x7f", b"nan", b"1e309"]


def mutate(rng, data):
    b = bytearray(data)
    for _ in range(rng.randint(1, 6)):
        op = rng.random()
        if op < 0.3 and b:
            b[rng.randrange(len(b))] = rng.randrange(256)
        elif op < 0.5 and b:
            i = rng.randrange(len(b))
            del b[i:i + rng.randint(1, 8)]
        elif op < 0.7:
            i = rng.randrange(len(b) + 1)
            b[i:i] = rng.choice(INSERTS)
        elif b:
            i, j = rng.randrange(len(b)), rng.randrange(len(b))
            b[i:i] = b[j:j + rng.randint(1, 16)]
    return bytes(b)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mhd", default=os.path.join(here, "..", "..", "build", "release", "tools", "mhd", "mhd"))
    ap.add_argument("--seconds", type=float, default=60.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=10.0, help="seconds a run may take")
    ap.add_argument("--out", default="probe_importers_out")
    ap.add_argument("--formats", default="", help="extensions to sweep, e.g. .3ds,.glb (default: all)")
    args = ap.parse_args()
    seeds = [(ext, seed) for ext, seed in sorted(SEEDS.items()) + MORE_SEEDS
             if not args.formats or ext in args.formats.split(",")]
    if not seeds:
        print("no seed for --formats %s" % args.formats)
        return 2
    rng = random.Random(args.seed)
    os.makedirs(args.out, exist_ok=True)
    env = dict(os.environ, MHD_CACHE_DIR=os.path.join(args.out, "cache"))
    def validate(ext, data):
        """`mhd validate` of a scene of one mesh holding `data`: its exit status, or None
        past the timeout, and its stderr."""
        with open(os.path.join(args.out, "mesh" + ext), "wb") as f:
            f.write(data)
        scene = os.path.join(args.out, "scene.xml")
        with open(scene, "w") as f:
            f.write('<scene version="1">\n<material name="m" stiffness_N_per_m="500"/>\n'
                    '<object name="a" material="m"><mesh file="mesh%s"/></object></scene>\n' % ext)
        try:
            r = subprocess.run([args.mhd, "validate", scene], capture_output=True, timeout=args.timeout, env=env)
            return r.returncode, r.stderr.decode(errors="replace")
        except subprocess.TimeoutExpired:
            return None, ""

    # The dual of the sweep: each seed as it is loads (SMD is refused unread), so that the
    # mutations start from files the readers take.
    for ext, seed in seeds:
        status, err = validate(ext, seed)
        if status != (1 if ext == ".smd" else 0):
            print("the %s seed does not load as it should (status %s): %s" % (ext, status, err.strip()))
            return 2
    kept = collections.Counter()
    runs = collections.Counter()
    start = time.monotonic()
    while time.monotonic() - start < args.seconds:
        ext, seed = rng.choice(seeds)
        data = mutate(rng, seed) if rng.random() < 0.9 else seed
        runs[ext] += 1
        status, _ = validate(ext, data)
        if status in (0, 1):
            continue
        kind = (ext, "timeout" if status is None else "exit %d" % status)
        if kept[kind] == 0:
            with open(os.path.join(args.out, "%s_%s%s" % (kind[1].replace(" ", "_"), sum(runs.values()), ext)),
                      "wb") as f:
                f.write(data)
        kept[kind] += 1
    print("%d runs (%s)" % (sum(runs.values()), ", ".join("%s %d" % kv for kv in sorted(runs.items()))))
    for (ext, what), n in sorted(kept.items()):
        print("%s: %d %s" % (ext, n, what))
    return 1 if kept else 0


if __name__ == "__main__":
    sys.exit(main())
