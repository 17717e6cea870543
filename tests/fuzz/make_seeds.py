#!/usr/bin/env python3
"""Writes the small seed corpora in tests/fuzz/corpus/<target>/ (run once; the files are committed).

Map PLY seeds come from our exporter: pass `--map-ply FILE` (e.g. from
`tunnelmap-cli detect resources/sample/lab --ply FILE`) to copy it in."""
import argparse, json, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")


def put(target, name, data):
    d = os.path.join(CORPUS, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


# ------------------------------------------------------------------ PNG
def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)


def png(w, h, depth, ctype, row_fn):
    raw = b"".join(b"\x00" + row_fn(v) for v in range(h))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def depth_row(w):
    return lambda v: b"".join(struct.pack(">H", 0 if (u + v) % 7 == 0 else 1000 + 13 * u + 29 * v) for u in range(w))


def png_seeds():
    good = png(16, 12, 16, 0, depth_row(16))
    put("depth_png", "depth16_16x12.png", good)
    put("depth_png", "depth16_zero.png", png(8, 6, 16, 0, lambda v: b"\x00\x00" * 8))
    put("depth_png", "grey8.png", png(8, 6, 8, 0, lambda v: bytes(range(8))))
    put("depth_png", "rgb8.png", png(4, 3, 8, 2, lambda v: b"\x10\x20\x30" * 4))
    put("depth_png", "truncated.png", good[: len(good) // 2])
    put("depth_png", "huge_header.png", b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 100000, 100000, 16, 0, 0, 0, 0)))


# ------------------------------------------------------------------ PCD
W, H = 8, 6


def cloud():
    pts = []
    for v in range(H):
        for u in range(W):
            z = 1.0 + 0.01 * u
            pts.append(((u - 3.5) * z / 10.0, (v - 2.5) * z / 10.0, z))
    pts[5] = (float("nan"),) * 3
    return pts


def pcd_header(data, fields="x y z", size="4 4 4", typ="F F F", count="1 1 1", w=W, h=H):
    return (f"# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS {fields}\nSIZE {size}\n"
            f"TYPE {typ}\nCOUNT {count}\nWIDTH {w}\nHEIGHT {h}\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {w * h}\nDATA {data}\n")


def lzf_literal(raw):
    # LZF with literal runs only (control byte = run length - 1, at most 32): valid, uncompressed.
    out = bytearray()
    for i in range(0, len(raw), 32):
        run = raw[i:i + 32]
        out.append(len(run) - 1)
        out += run
    return bytes(out)


def pcd_seeds():
    pts = cloud()
    ascii_body = "".join(f"{x} {y} {z}\n" for x, y, z in pts)
    put("pcd", "organised_ascii.pcd", pcd_header("ascii") + ascii_body)
    put("pcd", "organised_binary.pcd", pcd_header("binary").encode() + b"".join(struct.pack("<fff", *p) for p in pts))
    # binary_compressed stores the fields one after another (x of every point, then y, then z).
    soa = b"".join(struct.pack("<f", p[k]) for k in range(3) for p in pts)
    comp = lzf_literal(soa)
    put("pcd", "organised_compressed.pcd",
        pcd_header("binary_compressed").encode() + struct.pack("<II", len(comp), len(soa)) + comp)
    rgb = "".join(f"{x} {y} {z} 4.2108e+06\n" for x, y, z in pts)
    put("pcd", "organised_xyzrgb_ascii.pcd", pcd_header("ascii", "x y z rgb", "4 4 4 4", "F F F F", "1 1 1 1") + rgb)
    put("pcd", "absurd_points.pcd", pcd_header("binary", w=100000, h=10000))
    put("pcd", "inf_nan.pcd", pcd_header("ascii") + "".join("nan nan nan\n" if i % 2 else "inf 1 inf\n" for i in range(W * H)))


# ------------------------------------------------------------------ PLY
def ply_seeds(map_ply):
    if map_ply:
        with open(map_ply, "rb") as f:
            put("ply", "map_binary.ply", f.read())
    verts = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    faces = [(0, 1, 2), (0, 2, 3)]
    # mesh_ply layout: x y z nx ny nz red green blue, faces list uchar int.
    head = ("ply\nformat binary_little_endian 1.0\ncomment tunnelmap fused TSDF mesh\nelement vertex 4\n"
            "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
            "property float nz\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n")
    body = b"".join(struct.pack("<ffffffBBB", *v, 0, 0, 1, 200, 100, 50) for v in verts)
    body += b"".join(struct.pack("<Biii", 3, *f) for f in faces)
    put("ply", "mesh_binary.ply", head.encode() + body)
    # planes_ply layout: point cloud with an int plane id.
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
            "property int plane\nend_header\n")
    put("ply", "planes_binary.ply", head.encode() + b"".join(struct.pack("<fffBBBi", *v, 60, 120, 255, 2) for v in verts[:3]))
    ascii_ply = ("ply\nformat ascii 1.0\ncomment ascii map\nelement vertex 4\nproperty float x\nproperty float y\n"
                 "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
                 "property list uchar int vertex_indices\nproperty uchar label\nproperty uchar wall\nend_header\n"
                 + "".join(f"{x} {y} {z} 255 140 0\n" for x, y, z in verts) + "4 0 1 2 3 2 1\n")
    put("ply", "quad_ascii.ply", ascii_ply)
    put("ply", "truncated.ply", ascii_ply[: len(ascii_ply) - 20])


# ------------------------------------------------------------------ JSON
def json_seeds():
    eye = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    base = {"format": "tunnelmap-dataset/1",
            "intrinsics": {"fx": 3.6, "fy": 3.6, "cx": 1.5, "cy": 1.0, "width": 4, "height": 3},
            "depth_scale": 1000, "up": [0, 0, 1],
            "frames": [{"depth": "depth/000000.png", "rgb": "rgb/000000.png", "gt_surfaces": "gt/000000.png",
                        "pose": eye, "joints": [0.1, 0.2], "timestamp": 0.5}],
            "ground_truth": {"width_m": 0.82, "height_m": 1.3}}
    put("dataset_json", "valid.json", json.dumps(base))
    variants = {
        "escape_dotdot.json": "../outside.png", "escape_symlink.json": "link_out.png",
        "escape_root.json": "root/etc/hostname", "symlink_loop.json": "loop/000000.png",
        "absolute.json": "/etc/hostname", "grey8_depth.json": "depth/grey8.png",
    }
    for name, path in variants.items():
        d = json.loads(json.dumps(base))
        d["frames"][0]["depth"] = path
        put("dataset_json", name, json.dumps(d))
    d = json.loads(json.dumps(base)); d["frames"][0]["pose"] = ["1"] * 16
    put("dataset_json", "pose_strings.json", json.dumps(d))
    d = json.loads(json.dumps(base)); del d["intrinsics"]["fx"]
    put("dataset_json", "missing_fx.json", json.dumps(d))
    put("dataset_json", "malformed.json", json.dumps(base)[:-30])
    put("preset_json", "minimal.json", '{"params": {"grow.angle_deg": 4}}')
    put("preset_json", "unknown_key.json", '{"params": {"grow.nope": 1}}')
    put("preset_json", "out_of_range.json", '{"params": {"grow.angle_deg": 1e9}}')
    put("preset_json", "flat.json", '{"grow.distance_mm": 8, "tunnel.zone_cluster_mm": 4}')
    for f in ("lab.json", "field.json"):
        with open(os.path.join(HERE, "..", "..", "resources", "presets", f), "rb") as src:
            put("preset_json", f, src.read())


# ------------------------------------------------------------------ TUM lists
def tum_seeds():
    depth = ("# depth maps\n# file: 'rgbd_dataset_freiburg1_xyz.bag'\n# timestamp filename\n"
             "1305031102.160407 depth/1305031102.160407.png\n1305031102.194330 depth/1305031102.194330.png\n"
             "1305031102.226738 depth/1305031102.226738.png\n")
    gt = ("# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n"
          "1305031102.1500 1.3405 0.6266 1.6575 0.6574 0.6126 -0.2949 -0.3248\n"
          "1305031102.1900 1.3397 0.6256 1.6579 0.6583 0.6126 -0.2932 -0.3241\n"
          "1305031102.2300 1.3384 0.6255 1.6585 0.6589 0.6114 -0.2915 -0.3260\n")
    put("tum_list", "depth_list.txt", depth)
    put("tum_list", "groundtruth.txt", gt)
    put("tum_list", "paired.txt", depth + "%%\n" + gt)
    put("tum_list", "crlf.txt", depth.replace("\n", "\r\n") + "%%\n" + gt.replace("\n", "\r\n"))
    put("tum_list", "not_increasing.txt", "2.0 depth/a.png\n1.0 depth/b.png\n%%\n2.0 0 0 0 0 0 0 1\n1.0 0 0 0 0 0 0 1\n")
    put("tum_list", "bad_quaternion.txt", "1.0 depth/a.png\n%%\n1.0 0 0 0 0 0 0 2\n2.0 0 0 0 nan 0 0 1\n")
    put("tum_list", "fields.txt", "1.0\n2.0 a b\n%%\n1.0 0 0 0 0 0 1\n")
    put("tum_list", "huge_times.txt", "-1e308 a\n1e308 b\n%%\n-1e308 1e9 -1e9 1e9 0 0 0 1\n1e308 -1e9 1e9 -1e9 1 0 0 0\n")
    put("tum_list", "huge_translation.txt", "1 a\n%%\n1 1e300 0 0 0 0 0 1\n")


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--map-ply")
    a = ap.parse_args()
    png_seeds(); pcd_seeds(); ply_seeds(a.map_ply); json_seeds(); tum_seeds()
