// Checks on the raw bytes of a glTF file that tinygltf does not make, or makes too loosely:
// before parsing (the GLB container, the JSON nesting depth, what the file starts with) and
// after (optional integers tinygltf reads as absent when invalid), plus a clearer diagnosis of
// an unreadable buffer when tinygltf fails.
#pragma once

#include "scene/GltfFileAccess.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace gi::scene::gltf {

// Deepest nesting of JSON arrays/objects, ignoring brackets inside strings. tinygltf copies
// `extras` recursively, so a hostile nesting depth must be refused before it parses.
std::size_t jsonNestingDepth(const char* text, std::size_t size);

// Checks the GLB container (glTF 2.0 section 4.4) more strictly than tinygltf, which reads up to
// 8 bytes past a BIN chunk that claims more than the file holds. Finds the JSON chunk.
bool checkGlbContainer(const std::uint8_t* data, std::size_t size, const char*& json,
        std::size_t& jsonSize, std::string& what);

// The first bytes of a file that is neither GLB nor a JSON object, for the message.
std::string leadingBytes(const std::uint8_t* data, std::size_t size);

// True when the text's first character after an optional UTF-8 byte order mark and white
// space opens a JSON object.
bool startsLikeJsonObject(const char* text, std::size_t size);

// After tinygltf failed: a clearer message for the common cause, an unreadable external buffer.
std::string diagnoseBuffers(const char* json, std::size_t size, const FileAccess& access);

// tinygltf reads an optional index, byteOffset or byteStride that is negative or not an integer
// as if it were absent; glTF requires non-negative integers, so the JSON itself is checked.
// Returns "<element>: <what>" for the first offender, empty when there is none.
std::string checkOptionalIntegers(const char* json, std::size_t size);

} // namespace gi::scene::gltf
