// The atlas taken from a scene's own TEXCOORD_1 when that already is one (inside the unit
// square, no two triangles on one texel centre, nothing collapsed): charts are its connected
// components, and the texel size follows from the surface area over the texels covered.
#pragma once

#include "gi/atlas/AtlasBuilder.h"

namespace gi::atlas {

// Fills `atlas` from TEXCOORD_1, which texcoord1IsAtlas has accepted.
bool buildFromTexcoord1(const AtlasMesh& mesh, const AtlasOptions& options, Atlas& atlas);

} // namespace gi::atlas
