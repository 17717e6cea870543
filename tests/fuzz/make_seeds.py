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


# ------------------------------------------------------------------ ROS recordings
def cdr_string(s):
    b = s.encode() + b"\0"
    return struct.pack("<I", len(b)) + b


def cdr_image(w, h, encoding, data, step):
    # header (stamp, frame_id), height, width, encoding, is_bigendian, step, data; CDR alignment
    # matters only for the u32s after the strings, which cdr_align() pads.
    body = struct.pack("<iI", 12, 500) + cdr_string("cam")
    body = cdr_align(body, 4) + struct.pack("<II", h, w) + cdr_string(encoding)
    body += b"\0"
    body = cdr_align(body, 4) + struct.pack("<I", step)
    body += struct.pack("<I", len(data)) + data
    return b"\x00\x01\x00\x00" + body


def cdr_align(body, n):
    return body + b"\0" * ((-len(body)) % n)


def cdr_tf(parent, child, xyz):
    body = struct.pack("<I", 1) + struct.pack("<iI", 3, 7) + cdr_string(parent)
    body = cdr_align(body, 4) + cdr_string(child)
    body = cdr_align(body, 8) + struct.pack("<7d", *xyz, 0, 0, 0, 1)
    return b"\x00\x01\x00\x00" + body


def mcap_record(op, content):
    return struct.pack("<BQ", op, len(content)) + content


def mstr(s):
    return struct.pack("<I", len(s)) + s.encode()


def mcap_file(summary=True):
    magic = b"\x89MCAP0\r\n"
    out = magic + mcap_record(1, mstr("ros2") + mstr("seed"))
    schema = mcap_record(3, struct.pack("<H", 1) + mstr("sensor_msgs/msg/Image") + mstr("ros2msg") + mstr(""))
    channel = mcap_record(4, struct.pack("<HH", 1, 1) + mstr("/depth") + mstr("cdr") + struct.pack("<I", 0))
    msg = cdr_image(2, 2, "16UC1", struct.pack("<4H", 1000, 0, 1500, 65535), 4)
    records = schema + channel + mcap_record(5, struct.pack("<HIQQ", 1, 0, 10, 10) + msg)
    chunk_offset = len(out)
    out += mcap_record(6, struct.pack("<QQQI", 10, 10, len(records), 0) + mstr("") + struct.pack("<Q", len(records)) + records)
    chunk_length = len(out) - chunk_offset
    index_offset = len(out)
    out += mcap_record(7, struct.pack("<HI", 1, 16) + struct.pack("<QQ", 10, len(schema) + len(channel)))
    out += mcap_record(15, struct.pack("<I", 0))
    summary_start = len(out) if summary else 0
    if summary:
        out += schema + channel
        offsets = struct.pack("<HQ", 1, index_offset)
        out += mcap_record(8, struct.pack("<QQQQ", 10, 10, chunk_offset, chunk_length) + struct.pack("<I", len(offsets))
                           + offsets + struct.pack("<Q", index_offset - chunk_offset - chunk_length + 25) + mstr("")
                           + struct.pack("<QQ", len(records), len(records)))
    out += mcap_record(2, struct.pack("<QQI", summary_start, 0, 0)) + magic
    return out


def ros1_field(name, value):
    f = name.encode() + b"=" + value
    return struct.pack("<I", len(f)) + f


def ros1_record(fields, data):
    header = b"".join(ros1_field(k, v) for k, v in fields)
    return struct.pack("<I", len(header)) + header + struct.pack("<I", len(data)) + data


def ros1_bag():
    conn_data = b"".join(ros1_field(k, v.encode()) for k, v in
                         (("topic", "/tf"), ("type", "tf2_msgs/TFMessage"), ("md5sum", "94810edda583a504dfda3829e70d7eec"),
                          ("message_definition", "")))
    conn = ros1_record((("op", b"\x07"), ("conn", struct.pack("<I", 0)), ("topic", b"/tf")), conn_data)
    tf = struct.pack("<I", 1) + struct.pack("<III", 0, 3, 7) + struct.pack("<I", 4) + b"odom"
    tf += struct.pack("<I", 6) + b"camera" + struct.pack("<7d", 1, 2, 3, 0, 0, 0, 1)
    msg = ros1_record((("op", b"\x02"), ("conn", struct.pack("<I", 0)), ("time", struct.pack("<II", 3, 7))), tf)
    chunk_body = conn + msg
    head_len = 4096
    chunk_pos = 13 + head_len
    chunk = ros1_record((("op", b"\x05"), ("compression", b"none"), ("size", struct.pack("<I", len(chunk_body)))), chunk_body)
    index = ros1_record((("op", b"\x04"), ("ver", struct.pack("<I", 1)), ("conn", struct.pack("<I", 0)),
                         ("count", struct.pack("<I", 1))), struct.pack("<IIi", 3, 7, len(conn)))
    index_pos = chunk_pos + len(chunk) + len(index)
    info = ros1_record((("op", b"\x06"), ("ver", struct.pack("<I", 1)), ("chunk_pos", struct.pack("<Q", chunk_pos)),
                        ("start_time", struct.pack("<II", 3, 7)), ("end_time", struct.pack("<II", 3, 7)),
                        ("count", struct.pack("<I", 1))), struct.pack("<II", 0, 1))
    bag_header = ros1_record((("op", b"\x03"), ("index_pos", struct.pack("<Q", index_pos)),
                              ("conn_count", struct.pack("<I", 1)), ("chunk_count", struct.pack("<I", 1))), b"")
    bag_header = bag_header[:-4]  # the data block is padding up to 4096 bytes
    pad = head_len - len(bag_header) - 4
    bag_header += struct.pack("<I", pad) + b" " * pad
    return b"#ROSBAG V2.0\n" + bag_header + chunk + index + conn + info


def recording_seeds():
    put("mcap_records", "indexed.mcap", mcap_file(True))
    put("mcap_records", "no_summary.mcap", mcap_file(False))
    put("ros1_records", "tf.bag", ros1_bag())
    put("ros1_records", "cut.bag", ros1_bag()[:4500])
    put("cdr_messages", "depth_16uc1.cdr", cdr_image(2, 2, "16UC1", struct.pack("<4H", 1000, 0, 1500, 65535), 4))
    put("cdr_messages", "rgb8_short.cdr", cdr_image(640, 480, "rgb8", b"\1" * 30, 1920))
    put("cdr_messages", "tf.cdr", cdr_tf("odom", "camera", (1.0, 2.0, 3.0)))


# ------------------------------------------------------------------ OpenNI recording (.oni)
def oni_record(typ, node, fields=b"", payload=b"", undo=0):
    return struct.pack("<IIIIIQ", 0x0052494E, typ, node, 28 + len(fields), len(payload), undo) + fields + payload


def oni_text(s):
    return struct.pack("<I", len(s) + 1) + s.encode() + b"\0"


def oni_property(typ, node, name, data):
    return oni_record(typ, node, oni_text(name) + struct.pack("<I", len(data)) + data)


def code16z_table(values):
    """OpenNI's 16zT depth code: a table of the distinct values, then their indices as differences."""
    table = sorted(set(values))
    idx = [table.index(v) for v in values]
    out = struct.pack("<H", len(table)) + b"".join(struct.pack("<H", v) for v in table) + struct.pack("<H", idx[0])
    last, i = idx[0], 1
    while i < len(idx):
        run = 0
        while i + 2 * run + 1 < len(idx) and idx[i + 2 * run] == last and idx[i + 2 * run + 1] == last and run < 15:
            run += 1
        if run:
            out += bytes([0xE0 + run])
            i += 2 * run
            continue
        d = last - idx[i]
        if abs(d) <= 6:
            out += bytes([((d + 6) << 4) | 0x0D])
        elif -64 <= d <= 63:
            out += bytes([0xFF, d + 192])
        else:
            out += bytes([0xFF]) + struct.pack(">H", idx[i])
        last = idx[i]
        i += 1
    return out


def oni_stream(node, name, node_type, codec, frames, w, h, oni_format, bpp):
    added = oni_text(name) + struct.pack("<I", node_type) + codec + struct.pack("<IQQQ", frames, 0, 33333 * frames, 0)
    return (oni_record(13, node, added)
            + oni_property(3, node, "oniRequiredFrameSize", struct.pack("<Q", w * h * bpp))
            + oni_property(3, node, "xnSupportedMapOutputModesCount", struct.pack("<Q", 1))
            + oni_property(6, node, "xnSupportedMapOutputModes", struct.pack("<III", w, h, 30))
            + oni_property(6, node, "xnMapOutputMode", struct.pack("<III", w, h, 30))
            + oni_property(3, node, "oniPixelFormat", struct.pack("<Q", oni_format))
            + oni_property(6, node, "xnFOV", struct.pack("<dd", 1.0, 0.8))
            + oni_property(6, node, "xnCropping", struct.pack("<IHHHH", 0, 0, 0, w, h))
            + (oni_property(3, node, "xnDeviceMaxDepth", struct.pack("<Q", 10000)) if node_type == 2 else b""))


def oni_file(w=8, h=6, frames=2):
    """Depth (16zT) and colour (uncompressed) frames as OpenNI2's recorder lays them out."""
    body = oni_stream(1, "Depth", 2, b"16zT", frames, w, h, 100, 2) + oni_stream(2, "Image", 3, b"NONE", frames, w, h, 200, 3)
    body += oni_record(9, 1) + oni_record(8, 1, struct.pack("<IQ", 0xFFFFFFFF, 2**64 - 1))
    body += oni_record(9, 2) + oni_record(8, 2, struct.pack("<IQ", 0xFFFFFFFF, 2**64 - 1))
    for f in range(frames):
        depth = [0 if (u + v + f) % 5 == 0 else 1000 + 7 * u + 90 * v for v in range(h) for u in range(w)]
        rgb = bytes((u * 30 + v * 7 + f) & 0xFF for v in range(h) for u in range(w * 3))
        stamp = struct.pack("<QI", 33333 * f, f + 1)
        body += oni_record(10, 2, stamp, rgb) + oni_record(10, 1, stamp, code16z_table(depth))
    for node in (1, 2):
        body += oni_record(7, node) + oni_record(14, node, b"", b"\0" * 20 * (frames + 1))
    body += oni_record(11, 0)
    return b"NI10" + struct.pack("<BBHIQI", 1, 0, 1, 0, 2**64 - 1, 2) + body


def json_depth_seeds():
    put("json_depth", "depth64.json", "[" * 64 + "]" * 64)
    put("json_depth", "depth65.json", "[" * 65 + "]" * 65)
    put("json_depth", "brackets_in_strings.json", '{"a": "[[[[{{{{", "b": [[["\\"]]"]]], "c": {"d": [1, 2.5e3, null]}}')
    put("json_depth", "unclosed.json", '{"frames": [[[' + "[" * 100)


def oni_seeds():
    good = oni_file()
    put("oni_container", "depth_colour.oni", good)
    put("oni_container", "cut.oni", good[: len(good) // 2])
    put("oni_container", "one_frame.oni", oni_file(16, 4, 1))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--map-ply")
    a = ap.parse_args()
    png_seeds(); pcd_seeds(); ply_seeds(a.map_ply); json_seeds(); tum_seeds(); recording_seeds(); oni_seeds(); json_depth_seeds()
