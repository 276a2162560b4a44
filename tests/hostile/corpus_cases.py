"""The hostile-file cases: each starts from the valid triangle of corpus_gltf and breaks one
thing, and records the scene file, what is broken and the message fragment the loader must
print. Cases are listed in the order of the manifest, grouped by what they break."""
import base64
import copy
import struct

from corpus_gltf import (DOUBLE, FLOAT, NAN, U32_MAX, U64_MAX, UINT32, Raw, dump_json, embedded,
                         glb, png, textured_gltf, triangle)

CASES = []  # (scene file, what is broken, expected message fragment, {file: bytes})


def case(name, broken, fragment, content, extra=None):
    files = {name: content}
    files.update(extra or {})
    CASES.append((name, broken, fragment, files))


def mutated(mutate, textured=False):
    """The valid triangle as embedded .gltf after `mutate(doc)` edits its document."""
    doc, binary = triangle(textured)
    mutate(doc)
    return embedded(doc, binary)


def with_binary(patch):
    """The valid triangle as embedded .gltf with `patch(bytearray)` applied to its buffer."""
    doc, binary = triangle()
    data = bytearray(binary)
    patch(data)
    return embedded(doc, bytes(data))


def setter(path, value):
    """mutate function setting doc[path[0]][path[1]]... = value."""
    def mutate(doc):
        target = doc
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value
    return mutate


def build_cases():
    doc, binary = triangle()
    valid_glb = glb(doc, binary)
    valid_text = embedded(doc, binary)

    whole_file_cases(valid_text)
    glb_container_cases(doc, binary, valid_glb)
    buffer_cases(doc, binary)
    buffer_view_cases()
    accessor_cases(doc, binary)
    node_cases()
    primitive_cases()
    texture_cases()


def whole_file_cases(valid_text):
    """Whole files: empty, cut short, not glTF at all."""
    case("empty.gltf", "0-byte .gltf file", "file: is empty (0 bytes)", b"")
    case("empty.glb", "0-byte .glb file", "file: is empty (0 bytes)", b"")
    case("truncated_json.gltf", "the JSON text stops half way",
         "glTF: [json.exception.parse_error.101] parse error at line 40, column 5: syntax error "
         "while parsing value - unexpected end of input", valid_text[: len(valid_text) // 2])
    case("not_json.gltf", "plain text, not JSON",
         "file: is neither GLB (magic 'glTF') nor JSON text holding an object (it starts with "
         "bytes 74 68 69 73)", b"this is not a glTF file\n")
    case("json_array.gltf", "the top-level JSON value is an array, not an object",
         "file: is neither GLB (magic 'glTF') nor JSON text holding an object", b"[1, 2, 3]\n")
    case("json_object_cut.gltf", "an object that is never closed",
         "glTF: [json.exception.parse_error.101] parse error at line 1, column 21",
         b'{"asset":{"version":')
    case("binary_garbage.gltf", "random bytes, neither GLB nor JSON",
         "file: is neither GLB (magic 'glTF') nor JSON text holding an object (it starts with "
         "bytes 59 1e e3 a8)", bytes((i * 197 + 89) % 256 for i in range(256)))
    case("json_nested_deep.gltf", "extras nested 1000 arrays deep",
         "JSON: nesting deeper than 128 levels",
         b'{"asset":{"version":"2.0"},"extras":' + b"[" * 1000 + b"]" * 1000 + b"}\n")
    case("asset_missing.gltf", "no asset object (required)",
         "glTF: \"asset\" object not found in .gltf or not an object type",
         mutated(lambda d: d.pop("asset")))


def glb_container_cases(doc, binary, valid_glb):
    """The GLB container: header, chunk lengths and chunk types."""
    case("glb_truncated_header.glb", "a GLB cut off inside its 12-byte header",
         "GLB header: the file is 10 bytes, shorter than a GLB header", valid_glb[:10])
    case("glb_truncated.glb", "a GLB cut off inside its BIN chunk",
         "GLB header: header length %d exceeds the file size %d" % (len(valid_glb),
                                                                    len(valid_glb) - 9),
         valid_glb[:-9])
    truncated_json = bytearray(valid_glb[:60])
    truncated_json[8:12] = struct.pack("<I", 60)
    case("glb_truncated_json_chunk.glb",
         "a GLB cut off inside its JSON chunk (header length adjusted to match)",
         "GLB header: the first chunk is not a JSON chunk inside the file", bytes(truncated_json))
    case("glb_wrong_magic.glb", "magic 'gLTF' instead of 'glTF'",
         "file: is neither GLB (magic 'glTF') nor JSON text holding an object (it starts with "
         "bytes 67 4c 54 46)", glb(doc, binary, magic=b"gLTF"))
    case("glb_version_1.glb", "GLB container version 1", "GLB header: GLB version 1 is not 2",
         glb(doc, binary, version=1))
    case("glb_version_huge.glb", "GLB container version 0xFFFFFFFF",
         "GLB header: GLB version 4294967295 is not 2", glb(doc, binary, version=U32_MAX))
    wrong_length = bytearray(valid_glb)
    wrong_length[8:12] = struct.pack("<I", U32_MAX)
    case("glb_length_huge.glb", "header length 0xFFFFFFFF, far beyond the file",
         "GLB header: header length 4294967295 exceeds the file size", bytes(wrong_length))
    json_huge = bytearray(valid_glb)
    json_huge[12:16] = struct.pack("<I", 0xFFFFFFF0)
    case("glb_json_chunk_length_huge.glb", "JSON chunk length 0xFFFFFFF0",
         "GLB header: the first chunk is not a JSON chunk inside the file", bytes(json_huge))
    json_odd = bytearray(valid_glb)
    json_odd[12:16] = struct.pack("<I", struct.unpack("<I", valid_glb[12:16])[0] - 1)
    case("glb_json_chunk_length_unaligned.glb", "JSON chunk length not a multiple of 4",
         "GLB header: the JSON chunk length 507 is not a multiple of 4", bytes(json_odd))
    case("glb_json_chunk_type_wrong.glb", "the first chunk is typed BIN instead of JSON",
         "GLB header: the first chunk is not a JSON chunk inside the file",
         glb(doc, binary, json_type=b"BIN\x00"))
    case("glb_bin_chunk_length_huge.glb", "BIN chunk length 0xFFFFFFF0",
         "GLB header: the BIN chunk length 4294967280 is not a multiple of 4 that fits in the "
         "file", glb(doc, binary, bin_length=0xFFFFFFF0))
    case("glb_bin_chunk_missing.glb", "buffer 0 has no uri but the GLB has no BIN chunk",
         "glTF: Invalid binary data in `Buffer', or GLB with empty BIN chunk",
         glb(doc, b"", byte_length=len(binary)))


def buffer_cases(doc, binary):
    """Buffers: missing, short or empty files, lengths, data URIs."""
    case("buffer_file_missing.gltf", "buffers[0].uri names a file that does not exist",
         "buffers[0]: cannot read 'buffer_file_missing.bin' (No such file or directory)",
         external(doc, binary, "buffer_file_missing.bin"))
    case("buffer_file_empty.gltf", "buffers[0].uri names a 0-byte file",
         "buffers[0]: 'buffer_file_empty.bin' holds 0 bytes but byteLength is 44",
         external(doc, binary, "buffer_file_empty.bin"), {"buffer_file_empty.bin": b""})
    case("buffer_file_short.gltf", "the buffer file holds 20 of its 44 bytes",
         "buffers[0]: 'buffer_file_short.bin' holds 20 bytes but byteLength is 44",
         external(doc, binary, "buffer_file_short.bin"), {"buffer_file_short.bin": binary[:20]})
    case("buffer_bytelength_zero.gltf", "buffers[0].byteLength is 0 for a 44-byte buffer",
         "buffers[0]: the data URI holds 44 bytes but byteLength is 0",
         embedded(doc, binary, byte_length=0))
    case("buffer_bytelength_huge.gltf", "buffers[0].byteLength is 2^62 for a 44-byte file",
         "buffers[0]: 'buffer_bytelength_huge.bin' holds 44 bytes but byteLength is "
         "4611686018427387904", external(doc, binary, "buffer_bytelength_huge.bin", 2**62),
         {"buffer_bytelength_huge.bin": binary})
    case("buffer_data_uri_corrupt.gltf", "buffers[0].uri is a data URI of invalid base64",
         "buffers[0]: the data URI is not valid base64", corrupt_data_uri(doc))
    case("buffer_data_uri_long.gltf", "a 4 KiB data URI whose byteLength is 1 byte short",
         "buffers[0]: the data URI holds 4096 bytes but byteLength is 4095",
         embedded(doc, binary + bytes(4096 - len(binary)), byte_length=4095))


def buffer_view_cases():
    """Buffer views: offsets, lengths and strides."""
    case("bufferview_past_buffer.gltf", "bufferViews[1] ends at byte 1006 of a 44-byte buffer",
         "bufferViews[1]: byteOffset + byteLength (1006) exceeds buffers[0].byteLength (44)",
         mutated(setter(["bufferViews", 1, "byteOffset"], 1000)))
    case("bufferview_offset_overflow_u64.gltf",
         "bufferViews[0].byteOffset 2^64-1: offset + length overflows 64 bits",
         "bufferViews[0]: byteOffset + byteLength (more than 2^64) exceeds buffers[0]",
         mutated(setter(["bufferViews", 0, "byteOffset"], U64_MAX)))
    case("bufferview_offset_overflow_u32.glb",
         "bufferViews[0].byteOffset 2^32-1: offset + length overflows 32 bits",
         "bufferViews[0]: byteOffset + byteLength (4294967331) exceeds buffers[0].byteLength "
         "(44)", glb_mutated(setter(["bufferViews", 0, "byteOffset"], U32_MAX)))
    case("bufferview_offset_negative.gltf", "bufferViews[0].byteOffset is -4",
         "bufferViews[0]: byteOffset -4 is not an integer >= 0",
         mutated(setter(["bufferViews", 0, "byteOffset"], -4)))
    case("bufferview_length_zero.gltf", "bufferViews[0].byteLength is 0",
         "accessors[0]: byteOffset + (count-1)*stride + elementSize (36) exceeds "
         "bufferViews[0].byteLength (0)",
         mutated(setter(["bufferViews", 0, "byteLength"], 0)))
    case("bufferview_stride_huge.gltf", "bufferViews[0].byteStride is 4096 (at most 252)",
         "glTF: Invalid `byteStride' value. `byteStride' must be the multiple of 4 : 4096",
         mutated(setter(["bufferViews", 0, "byteStride"], 4096)))
    case("bufferview_stride_unaligned.gltf", "bufferViews[0].byteStride is 13",
         "glTF: Invalid `byteStride' value. `byteStride' must be the multiple of 4 : 13",
         mutated(setter(["bufferViews", 0, "byteStride"], 13)))
    case("bufferview_stride_too_small.gltf",
         "bufferViews[0].byteStride is 4 for 12-byte VEC3 elements",
         "bufferViews[0]: byteStride 4 is smaller than the 12-byte elements of accessors[0]",
         mutated(setter(["bufferViews", 0, "byteStride"], 4)))
    case("bufferview_stride_negative.gltf", "bufferViews[0].byteStride is -12",
         "bufferViews[0]: byteStride -12 is not an integer >= 0",
         mutated(setter(["bufferViews", 0, "byteStride"], -12)))
    case("bufferview_buffer_missing.gltf", "bufferViews[0].buffer is 7 (the file has 1)",
         "bufferViews[0]: buffer 7 does not exist (the file has 1 buffers)",
         mutated(setter(["bufferViews", 0, "buffer"], 7)))


def accessor_cases(doc, binary):
    """Accessors: counts, offsets, types, sparse data, non-finite values, indices."""
    case("accessor_past_bufferview.gltf", "accessors[0].count is 100 in a 36-byte view",
         "accessors[0]: byteOffset + (count-1)*stride + elementSize (1200) exceeds "
         "bufferViews[0].byteLength (36)", mutated(setter(["accessors", 0, "count"], 100)))
    case("accessor_offset_past_bufferview.gltf", "accessors[0].byteOffset is 1000",
         "accessors[0]: byteOffset 1000 exceeds bufferViews[0].byteLength (36)",
         mutated(setter(["accessors", 0, "byteOffset"], 1000)))
    case("accessor_offset_negative.gltf", "accessors[0].byteOffset is -12",
         "accessors[0]: byteOffset -12 is not an integer >= 0",
         mutated(setter(["accessors", 0, "byteOffset"], -12)))
    case("accessor_count_huge.gltf", "accessors[0].count is 2^40",
         "accessors[0]: byteOffset + (count-1)*stride + elementSize (13194139533312) exceeds "
         "bufferViews[0].byteLength (36)", mutated(setter(["accessors", 0, "count"], 2**40)))
    case("accessor_count_overflow.gltf", "accessors[0].count is 2^62: count * 12 overflows",
         "accessors[0]: byteOffset + (count-1)*stride + elementSize (more than 2^64) exceeds "
         "bufferViews[0].byteLength (36)", mutated(setter(["accessors", 0, "count"], 2**62)))
    case("accessor_count_huge_zeros.gltf",
         "accessors[0] has no bufferView (all zeros) and count 2^40",
         "accessors[0]: count 1099511627776 exceeds the loader's limit",
         mutated(lambda d: (d["accessors"][0].pop("bufferView"),
                            d["accessors"][0].update(count=2**40))))
    case("accessor_count_negative.gltf", "accessors[0].count is -1",
         "glTF: 'count' property is not a positive integer",
         mutated(setter(["accessors", 0, "count"], -1)))
    case("accessor_component_type_double.gltf", "accessors[0].componentType is 5130 (DOUBLE)",
         "accessors[0]: componentType 5130 is not one glTF 2.0 allows",
         mutated(setter(["accessors", 0, "componentType"], DOUBLE)))
    case("accessor_type_unknown.gltf", "accessors[0].type is VEC7",
         "glTF: Unsupported `type` for accessor object. Got \"VEC7\"",
         mutated(setter(["accessors", 0, "type"], "VEC7")))
    case("accessor_bufferview_missing.gltf", "accessors[0].bufferView is 9 (the file has 2)",
         "accessors[0]: bufferView 9 does not exist (the file has 2 bufferViews)",
         mutated(setter(["accessors", 0, "bufferView"], 9)))
    case("attribute_accessor_missing.gltf", "POSITION names accessor 5 (the file has 2)",
         "meshes[0].primitives[0]: attribute POSITION 5 does not exist (the file has 2 "
         "accessors)", mutated(setter(["meshes", 0, "primitives", 0, "attributes", "POSITION"],
                                      5)))
    case("attribute_count_mismatch.gltf", "NORMAL has 2 elements, POSITION 3",
         "meshes[0].primitives[0]: NORMAL has 2 elements but POSITION has 3",
         mutated(normal_count_mismatch))
    case("position_missing.gltf", "a triangle primitive without POSITION",
         "meshes[0].primitives[0]: has no POSITION attribute",
         mutated(lambda d: d["meshes"][0]["primitives"][0]["attributes"].pop("POSITION")))
    case("position_nan.gltf", "a NaN vertex coordinate in the buffer",
         "accessors[0]: element 1 (nan, 0, 0) is not finite (POSITION of "
         "meshes[0].primitives[0])", with_binary(lambda b: b.__setitem__(
             slice(12, 16), struct.pack("<f", NAN))))
    case("position_inf.gltf", "an infinite vertex coordinate in the buffer",
         "accessors[0]: element 2 (0, inf, 0) is not finite", with_binary(
             lambda b: b.__setitem__(slice(28, 32), struct.pack("<f", float("inf")))))
    case("index_out_of_range.gltf", "index 7 on a 3-vertex primitive",
         "accessors[1]: index 7 at element 2 is out of range (POSITION of "
         "meshes[0].primitives[0] has 3 vertices)",
         with_binary(lambda b: b.__setitem__(slice(40, 42), struct.pack("<H", 7))))
    case("index_max_uint32.gltf", "index 0xFFFFFFFF as UNSIGNED_INT",
         "accessors[1]: index 4294967295 at element 0 is out of range",
         index_u32_max(doc, binary))
    case("indices_float.gltf", "the indices accessor holds floats",
         "accessors[1]: indices must be SCALAR, not normalized, UNSIGNED_BYTE",
         mutated(lambda d: d["accessors"][1].update(componentType=FLOAT, bufferView=0)))
    case("sparse_index_out_of_range.gltf", "a sparse index 99 on a 3-element accessor",
         "accessors[0]: sparse index 99 (entry 0) is out of range (count 3)",
         sparse(99, 1))
    case("sparse_count_too_large.gltf", "sparse.count 10 on a 3-element accessor",
         "accessors[0]: sparse.count 10 is outside [1, count = 3]", sparse(0, 10))


def node_cases():
    """The node hierarchy and node transforms."""
    case("node_own_child.gltf", "nodes[0] lists itself as its child",
         "nodes[0]: is part of a cycle in the node hierarchy (nodes[0] -> nodes[0])",
         mutated(setter(["nodes", 0, "children"], [0])))
    case("node_cycle_2.gltf", "nodes[1] and nodes[2] are each other's child",
         "nodes[1]: is part of a cycle in the node hierarchy (nodes[1] -> nodes[2] -> nodes[1])",
         mutated(lambda d: d["nodes"].extend([{"children": [2]}, {"children": [1]}])))
    case("node_cycle_long.gltf", "a 200-node cycle unreachable from the scene",
         "nodes[1]: is part of a cycle in the node hierarchy (nodes[1] -> nodes[2] -> nodes[3] -> "
         "nodes[4] -> nodes[5] -> nodes[6] -> nodes[7] -> nodes[8] -> ... -> nodes[1])",
         mutated(lambda d: d["nodes"].extend(
             {"children": [1 + (i + 1) % 200]} for i in range(200))))
    case("node_two_parents.gltf", "nodes[2] is a child of both nodes[0] and nodes[1]",
         "nodes[2]: has two parents (nodes[0] and nodes[1])",
         mutated(lambda d: d.update(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}],
                                    scenes=[{"nodes": [0, 1]}])))
    case("node_child_missing.gltf", "nodes[0].children names node 5 (the file has 1)",
         "nodes[0]: child 5 does not exist (the file has 1 nodes)",
         mutated(setter(["nodes", 0, "children"], [5])))
    case("node_child_negative.gltf", "nodes[0].children holds -1",
         "nodes[0]: child -1 does not exist (the file has 1 nodes)",
         mutated(setter(["nodes", 0, "children"], [-1])))
    case("node_mesh_missing.gltf", "nodes[0].mesh is 3 (the file has 1)",
         "nodes[0]: mesh 3 does not exist (the file has 1 meshes)",
         mutated(setter(["nodes", 0, "mesh"], 3)))
    case("node_matrix_nan.gltf", "NaN in nodes[0].matrix (written as the token NaN)",
         "glTF: [json.exception.parse_error.101] parse error at line 18, column 5",
         mutated(setter(["nodes", 0, "matrix"], [Raw("NaN")] + [0] * 15)))
    case("node_matrix_inf.gltf", "nodes[0].matrix holds 1e999 (infinite)",
         "glTF: [json.exception.out_of_range.406] number overflow parsing '1e999'",
         mutated(setter(["nodes", 0, "matrix"], identity_matrix(Raw("1e999")))))
    case("node_matrix_float_overflow.gltf",
         "nodes[0].matrix holds 3.5e38, finite in JSON but not as a float",
         "nodes[0]: matrix must be 16 finite numbers",
         mutated(setter(["nodes", 0, "matrix"], identity_matrix(Raw("3.5e38")))))
    case("node_matrix_short.gltf", "nodes[0].matrix has 15 numbers",
         "nodes[0]: matrix must be 16 finite numbers",
         mutated(setter(["nodes", 0, "matrix"], [1] + [0] * 14)))
    case("node_translation_inf.gltf", "nodes[0].translation holds -1e999",
         "glTF: [json.exception.out_of_range.406] number overflow parsing '-1e999'",
         mutated(setter(["nodes", 0, "translation"], [0, Raw("-1e999"), 0])))
    case("node_translation_float_overflow.gltf",
         "nodes[0].translation holds 1e39, finite in JSON but not as a float",
         "nodes[0]: translation must be 3 finite numbers",
         mutated(setter(["nodes", 0, "translation"], [Raw("1e39"), 0, 0])))
    case("node_scale_float_overflow.gltf", "nodes[0].scale holds 1e300",
         "nodes[0]: scale must be 3 finite numbers",
         mutated(setter(["nodes", 0, "scale"], [1, 1, 1e300])))
    case("node_rotation_zero.gltf", "nodes[0].rotation is the zero quaternion",
         "nodes[0]: rotation is not a unit quaternion",
         mutated(setter(["nodes", 0, "rotation"], [0, 0, 0, 0])))
    case("node_world_overflow.gltf", "two nested scales of 1e30 overflow the world transform",
         "nodes[1]: world transform is not finite",
         mutated(lambda d: d.update(nodes=[{"scale": [1e30] * 3, "children": [1]},
                                           {"scale": [1e30] * 3, "mesh": 0}])))
    case("node_far_away.gltf", "the triangle is placed 1e30 m from the origin",
         "nodes[0]: places vertices beyond +-1e18 m",
         mutated(setter(["nodes", 0, "translation"], [1e30, 0, 0])))
    case("scene_node_missing.gltf", "scenes[0].nodes names node 4 (the file has 1)",
         "scenes[0]: node 4 does not exist (the file has 1 nodes)",
         mutated(setter(["scenes", 0, "nodes"], [4])))
    case("scene_default_missing.gltf", "scene is 3 (the file has 1 scene)",
         "scene: scene 3 does not exist (the file has 1 scenes)", mutated(setter(["scene"], 3)))


def primitive_cases():
    """Primitives, materials and extensions."""
    case("primitive_mode_invalid.gltf", "mode 7 (glTF defines 0..6)",
         "meshes[0].primitives[0]: mode 7 is not a glTF primitive mode",
         mutated(setter(["meshes", 0, "primitives", 0, "mode"], 7)))
    case("primitive_material_missing.gltf", "material 2 (the file has none)",
         "meshes[0].primitives[0]: material 2 does not exist (the file has 0 materials)",
         mutated(setter(["meshes", 0, "primitives", 0, "material"], 2)))
    case("extension_required_unsupported.gltf", "requires KHR_draco_mesh_compression",
         "extensionsRequired: extension 'KHR_draco_mesh_compression' is not supported",
         mutated(lambda d: d.update(extensionsUsed=["KHR_draco_mesh_compression"],
                                    extensionsRequired=["KHR_draco_mesh_compression"])))


def texture_cases():
    """Textures and the images they decode."""
    case("texture_file_missing.gltf", "the image file does not exist",
         "images[0]: cannot read 'texture_file_missing.png' (No such file or directory)",
         textured_gltf("texture_file_missing.png"))
    case("texture_empty.gltf", "the image file has 0 bytes",
         "images[0]: 'texture_empty.png' is empty (0 bytes)", textured_gltf("texture_empty.png"),
         {"texture_empty.png": b""})
    case("texture_not_an_image.gltf", "the .png file holds text",
         "images[0]: 'texture_not_an_image.png': not a PNG or JPEG image",
         textured_gltf("texture_not_an_image.png"),
         {"texture_not_an_image.png": b"this is not an image\n"})
    good_png = png(4, 4)
    case("texture_truncated.gltf", "the PNG stops inside its IDAT chunk",
         "images[0]: 'texture_truncated.png': cannot decode the image (Corrupt PNG)",
         textured_gltf("texture_truncated.png"),
         {"texture_truncated.png": good_png[:45]})
    corrupt = bytearray(good_png)
    corrupt[41:49] = b"\xff" * 8
    case("texture_corrupt.gltf", "the PNG's compressed pixel data is overwritten",
         "images[0]: 'texture_corrupt.png': cannot decode the image (Corrupt PNG)",
         textured_gltf("texture_corrupt.png"),
         {"texture_corrupt.png": bytes(corrupt)})
    case("texture_huge.gltf", "a PNG header claiming 65535 x 65535 pixels",
         "images[0]: 'texture_huge.png': a PNG stb_image cannot read (Image too large to decode)",
         textured_gltf("texture_huge.png"),
         {"texture_huge.png": png(65535, 65535, rows=b"")})
    case("texture_zero_size.gltf", "a PNG header claiming 0 x 0 pixels",
         "images[0]: 'texture_zero_size.png': a PNG stb_image cannot read (Corrupt PNG)",
         textured_gltf("texture_zero_size.png"),
         {"texture_zero_size.png": png(0, 0, rows=b"")})
    case("texture_source_missing.gltf", "textures[0].source is 4 (the file has 1 image)",
         "textures[0]: source 4 does not exist (the file has 1 images)",
         mutated(lambda d: (setter(["textures", 0, "source"], 4)(d),
                            setter(["images", 0, "uri"], "unused.png")(d)), textured=True))
    case("texture_data_uri_corrupt.gltf", "the image is a data URI of bytes that are no image",
         "images[0]: a PNG stb_image cannot read (Corrupt PNG)",
         mutated(setter(["images", 0, "uri"],
                                       "data:image/png;base64," +
                                       base64.b64encode(b"\x89PNG\r\n\x1a\nbroken").decode()),
                                textured=True))
    case("image_bufferview_past_buffer.glb", "the image's bufferView lies past the GLB buffer",
         "images[0]: bufferViews[3] does not lie inside its buffer", glb_image_past_buffer())

def identity_matrix(first):
    """A column-major identity matrix whose first element is `first`."""
    return [first, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]


def external(doc, binary, uri, byte_length=None):
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{"byteLength": len(binary) if byte_length is None else byte_length,
                       "uri": uri}]
    return dump_json(doc)


def glb_mutated(mutate):
    doc, binary = triangle()
    mutate(doc)
    return glb(doc, binary)


def corrupt_data_uri(doc):
    doc = copy.deepcopy(doc)
    doc["buffers"] = [{"byteLength": 44,
                       "uri": "data:application/octet-stream;base64,!!!!not*base64!!!!"}]
    return dump_json(doc)


def normal_count_mismatch(doc):
    doc["bufferViews"].append({"buffer": 0, "byteOffset": 0, "byteLength": 24})
    doc["accessors"].append({"bufferView": 2, "componentType": FLOAT, "count": 2,
                             "type": "VEC3"})
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2


def index_u32_max(doc, binary):
    doc = copy.deepcopy(doc)
    binary = binary[:36] + struct.pack("<3I", U32_MAX, 1, 2)
    doc["bufferViews"][1]["byteLength"] = 12
    doc["accessors"][1]["componentType"] = UINT32
    return embedded(doc, binary)


def sparse(index, count):
    """POSITION with a sparse substitution of `count` entries, the first at element `index`."""
    doc, binary = triangle()
    offset = len(binary)
    binary += struct.pack("<I", index) + struct.pack("<3f", 0.5, 0.5, 0.0)
    doc["bufferViews"] += [{"buffer": 0, "byteOffset": offset, "byteLength": 4},
                           {"buffer": 0, "byteOffset": offset + 4, "byteLength": 12}]
    doc["accessors"][0]["sparse"] = {
        "count": count,
        "indices": {"bufferView": 2, "componentType": UINT32},
        "values": {"bufferView": 3},
    }
    return embedded(doc, binary)


def glb_image_past_buffer():
    doc, binary = triangle(textured=True)
    doc["bufferViews"].append({"buffer": 0, "byteOffset": 64, "byteLength": 4096})
    doc["images"] = [{"bufferView": 3, "mimeType": "image/png"}]
    return glb(doc, binary)

