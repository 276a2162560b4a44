"""Building blocks of the hostile-file corpus: a valid one-triangle glTF scene, and its forms
as .gltf text with an embedded or external buffer, as GLB, and small PNG images, all written
byte for byte the same on every run (JSON layout fixed, PNG data stored uncompressed)."""
import base64
import copy
import json
import struct
import zlib

FLOAT, UINT16, UINT32, DOUBLE = 5126, 5123, 5125, 5130
U64_MAX = 2**64 - 1
U32_MAX = 2**32 - 1

POSITIONS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]
TEXCOORDS = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
NAN = struct.unpack("<f", b"\x00\x00\xc0\x7f")[0]


class Raw:
    """A JSON value written verbatim (NaN, 1e999, 3.5e38): what json.dumps cannot produce."""

    def __init__(self, text):
        self.text = text


def dump_json(doc):
    raws = []

    def mark(value):
        if isinstance(value, Raw):
            raws.append(value.text)
            return "\u0000raw%d\u0000" % (len(raws) - 1)
        if isinstance(value, dict):
            return {k: mark(v) for k, v in value.items()}
        if isinstance(value, list):
            return [mark(v) for v in value]
        return value

    text = json.dumps(mark(doc), indent=1)
    for i, raw in enumerate(raws):
        text = text.replace('"\\u0000raw%d\\u0000"' % i, raw)
    return text.encode() + b"\n"


def pad4(data, fill=b"\x00"):
    return data + fill * (-len(data) % 4)


def triangle(textured=False):
    """A valid one-triangle scene: (document, binary buffer). The buffer is not yet attached."""
    binary = b"".join(struct.pack("<3f", *p) for p in POSITIONS)
    binary += pad4(struct.pack("<3H", 0, 1, 2))
    doc = {
        "asset": {"version": "2.0", "generator": "voxatlas tests/hostile/make_corpus.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": FLOAT, "count": 3, "type": "VEC3",
             "min": [0, 0, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": UINT16, "count": 3, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 36},
            {"buffer": 0, "byteOffset": 36, "byteLength": 6},
        ],
    }
    if textured:
        doc["bufferViews"].append({"buffer": 0, "byteOffset": len(binary), "byteLength": 24})
        binary += b"".join(struct.pack("<2f", *t) for t in TEXCOORDS)
        doc["accessors"].append(
            {"bufferView": 2, "componentType": FLOAT, "count": 3, "type": "VEC2"})
        primitive = doc["meshes"][0]["primitives"][0]
        primitive["attributes"]["TEXCOORD_0"] = 2
        primitive["material"] = 0
        doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        doc["textures"] = [{"source": 0}]
        doc["images"] = [{"uri": "IMAGE"}]
    return doc, binary


def data_uri(binary):
    return "data:application/octet-stream;base64," + base64.b64encode(binary).decode()


def embedded(doc, binary, byte_length=None):
    """`doc` as .gltf text with `binary` as its base64-embedded buffer 0."""
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{"byteLength": len(binary) if byte_length is None else byte_length,
                       "uri": data_uri(binary)}]
    return dump_json(doc)


def glb(doc, binary, version=2, magic=b"glTF", bin_length=None, json_type=b"JSON",
        byte_length=None):
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{"byteLength": len(binary) if byte_length is None else byte_length}]
    text = pad4(json.dumps(doc, separators=(",", ":")).encode(), b" ")
    body = struct.pack("<I", len(text)) + json_type + text
    if binary:
        chunk = pad4(binary)
        length = len(chunk) if bin_length is None else bin_length
        body += struct.pack("<I", length) + b"BIN\x00" + chunk
    return magic + struct.pack("<II", version, 12 + len(body)) + body


def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(
        ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def zlib_stored(data):
    """A zlib stream of stored (uncompressed) blocks: the same bytes whatever zlib is installed."""
    blocks = [data[i:i + 65535] for i in range(0, len(data), 65535)] or [b""]
    out = b"\x78\x01"
    for i, block in enumerate(blocks):
        final = 1 if i == len(blocks) - 1 else 0
        out += struct.pack("<BHH", final, len(block), len(block) ^ 0xFFFF) + block
    return out + struct.pack(">I", zlib.adler32(data))


def png(width, height, rows=None):
    """An RGB PNG; `rows` (raw scanlines with filter bytes) default to a grey image."""
    if rows is None:
        rows = (b"\x00" + b"\x80" * 3 * width) * height
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) +
            png_chunk(b"IDAT", zlib_stored(rows)) + png_chunk(b"IEND", b""))


def textured_gltf(image_name):
    doc, binary = triangle(textured=True)
    doc["images"][0]["uri"] = image_name
    return embedded(doc, binary)
