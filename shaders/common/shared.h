// The one place where binding slots and GPU struct layouts are written. Included by C++
// (through gl/Shared.h, which maps the GLSL types onto glm) and by GLSL, so the two can
// never disagree. Structs use std140/std430-safe members only: vec4, mat4, ivec4 and
// scalars, with explicit padding (no vec3: its alignment differs between the two sides).
#ifndef GI_SHARED_H
#define GI_SHARED_H

// Uniform buffers.
#define BIND_UBO_FRAME              0   // FrameUniforms, one per rendered view

#define BIND_UBO_VOXEL              1   // VoxelUniforms: cascade placement and trace parameters
#define BIND_UBO_ATLAS              2   // AtlasUniforms: atlas size, sample set, estimator
#define BIND_UBO_VPL                3   // VplUniforms: VPL count, interleaving, clamp
#define BIND_UBO_SVO                4   // SvoUniforms: the sparse voxel octree's cube and depth

// Shader storage buffers.
#define BIND_SSBO_LIGHTS            0   // GpuLight[], every light of the scene
#define BIND_SSBO_MATERIALS         1   // GpuMaterial[], indexed by the draw's material
#define BIND_SSBO_SHADOWS           2   // GpuShadow[], one per light, same index as GpuLight
#define BIND_SSBO_ATLAS_SENDER_ROWS 3   // vec2[R]: prefix sums over atlas rows of the texels'
                                        // a(y) mean(L(y)) I(y) (x) and a(y) mean(L(y)) (y, W/sr),
                                        // I the importance (1 with atlas.importance=power);
                                        // the last holds the totals
#define BIND_SSBO_ATLAS_SENDER_BLOCKS 4 // vec2[R x ceil(R / ATLAS_SENDER_BLOCK)]: per row, the
                                        // same prefix sums at each block's end
#define BIND_SSBO_ATLAS_SENDER_POOL 5   // uint[N x ATLAS_POOL_STRIDE]: the area estimator's
                                        // sender texels (y R + x) of the current sample set,
                                        // ATLAS_POOL_STRIDE per stratum; ~0u = none
#define BIND_SSBO_SCENE_VERTICES    6   // float[14 per vertex]: GpuScene's vertices (SceneVertex)
#define BIND_SSBO_ATLAS_VERTICES    7   // float[18 per vertex]: the atlas' vertices (GpuAtlasVertex)
#define BIND_SSBO_ATLAS_SOURCES     8   // uint[]: per atlas vertex, the scene vertex it copies
#define BIND_SSBO_EMITTERS          9   // GpuEmitter[], the triangles of every area light
#define BIND_SSBO_BVH_NODES         10  // vec4[2 per node]: the scene's BVH (reference/GpuBvh.h)
#define BIND_SSBO_BVH_TRIANGLES     11  // vec4[3 per triangle]: its triangles' corners
#define BIND_SSBO_LINESPACE_NODES   12  // GpuLineSpaceHeader, then uint per child of every node
                                        // above the deepest inner level: the child's node index
                                        // or LINESPACE_EMPTY (render/LineSpaceShadows.h)
#define BIND_SSBO_LINESPACE_BITS    13  // uint[]: every node's line space, one bit per shaft
#define BIND_SSBO_LINESPACE_OCCUPANCY 14 // uint[] bits, build only: per N-tree level l = 0..d,
                                        // (N^l)^3 cells, x fastest; level d = the leaf voxels
#define BIND_SSBO_VPLS              16  // GpuVpl[], the virtual point lights of gi/vpl
#define BIND_SSBO_VPL_BOUNCES       17  // GpuVpl[], vpl.bounces=2: one per bounce ray, where it
                                        // stopped; flux 0 = it left the scene
#define BIND_SSBO_LINESPACE_INPUT   15  // build only: vec4[3 per triangle] world corners
                                        // (voxelization), or uvec4 (level, cell.xyz) per node
                                        // (line-space bits)
#define BIND_SSBO_SVO_NODES         18  // uint per node of the sparse voxel octree (gi/vpl):
                                        // SVO_NODE_FLAG | index of its first of 8 children
#define BIND_SSBO_SVO_FRAGMENTS     19  // build only: uint count, then one packed leaf voxel
                                        // (SVO_COORD_BITS per axis) per occupied leaf
#define BIND_SSBO_SVO_LEAF_BITS     20  // build only: uint[] one bit per leaf voxel, x fastest
#define BIND_SSBO_SVO_BUILD         21  // build only: SvoBuildState
#define BIND_SSBO_ATLAS_RECEIVERS   22  // vec4[2 x cells]: the receivers atlas.importance weighs
                                        // the senders by: position (w = its weight: 1 for the
                                        // view's, the area in m^2 it stands for for the
                                        // surfaces'; 0 where none is) and normal (w = 1 when
                                        // both sides receive); the surfaces the camera sees in
                                        // a grid of cells (view) or points on the scene's
                                        // triangles (surfaces)
#define BIND_SSBO_ATLAS_SURFACE_POINTS 23 // uint[SURFACE_POINT_UINTS x points]: the surfaces'
                                        // receivers as triangles and barycentric weights
                                        // (atlas::SurfacePoint)
#define BIND_SSBO_ATLAS_INDICES     24  // uint[3 per triangle]: the atlas' triangles, in the
                                        // scene's order (atlas::AtlasGeometry)

// Texture units for samplers.
#define BIND_TEX_BASE_COLOR         0   // sRGB8_A8 base colour of the current draw
#define BIND_TEX_EMISSIVE           1   // sRGB8_A8 emissive of the current draw
#define BIND_TEX_SHADOW_2D          2   // depth 2D array, spot and directional shadow maps
#define BIND_TEX_SHADOW_CUBE        3   // depth cube-map array, point-light shadow maps
#define BIND_TEX_PRESENT_SOURCE     2   // RGBA32F linear radiance the viewer presents

#define BIND_TEX_INDIRECT           4   // rgba16f screen-space E_ind (W/m^2), a = view depth (m)
#define BIND_TEX_INDIRECT_SPECULAR  24  // rgba16f screen-space indirect specular radiance
                                        // (W/(m^2 sr)), a = view depth (m); voxel GI with
                                        // material.model=gltf, same size as BIND_TEX_INDIRECT
#define BIND_TEX_VOXEL_ALBEDO       5   // sampler3D rgba16f, rgb = albedo x coverage, a = coverage
#define BIND_TEX_VOXEL_IRRADIANCE   6   // sampler3D rgba16f, rgb = irradiance E (W/m^2)
#define BIND_TEX_VOXEL_NORMAL       7   // sampler3D rgba8_snorm, xyz = mean normal, w = the
                                        // surface's offset from the voxel centre along it
                                        // (voxel sizes)
#define BIND_TEX_FILTER_SOURCE      8   // sampler2D rgba16f, traced E_ind + view depth
#define BIND_TEX_VOXEL_PYRAMID      9   // sampler3D rgba16f mipmapped, the coarsest level
                                        // averaged 2^(m+1) voxels per axis at mip m:
                                        // rgb = rho E x coverage (W/m^2), a = coverage;
                                        // with voxel.anisotropic 6 x-slabs, one per face,
                                        // as BIND_TEX_VOXEL_DIRECTIONAL
#define BIND_TEX_VOXEL_DIRECTIONAL  15  // sampler3D rgba16f (6v, v, v*l), voxel.anisotropic:
                                        // x-slab f = the voxel seen from face f (VOXEL_FACE_*),
                                        // rgb = rho E x a (W/m^2), a = how much of the
                                        // face the surfaces facing it cover
#define BIND_TEX_VOXEL_EDGE_FACES   27  // sampler3D rgba8_snorm (2v, v, v), the occupancy's
                                        // level 0 only: an edge voxel's two faces at x-slabs
                                        // 2x and 2x + 1 (voxel_edge_faces.glsl)

// Texture units of the atlas passes (gi/atlas). Atlas layers are R x R, texel (i, j) covers
// atlas coordinates [i, i+1) x [j, j+1) / R; alpha 0 = no surface.
#define BIND_TEX_ATLAS_DIRECT       8   // rgba16f, rgb = outgoing direct radiance of the surface,
                                        // rho/pi * E_dir + L_emitted (W/(m^2 sr)), a = coverage
#define BIND_TEX_ATLAS_NORMAL       9   // rgba16f, xyz = unit normal, w = 1 if double-sided
#define BIND_TEX_ATLAS_POSITION     10  // rgba32f, xyz = world position (m), w = surface area the
                                        // texel stands for as a gather sample (m^2): the area
                                        // of the triangles inside the texel square
#define BIND_TEX_ATLAS_ALBEDO       11  // rgba16f, rgb = albedo rho (linear), a = coverage
#define BIND_TEX_ATLAS_SAMPLES      12  // rg32f, N x 1 Hammersley points in [0,1)^2
#define BIND_TEX_ATLAS_SUMS         13  // rgba32f, gather sums over every sample set so far,
                                        // a = 1 where a receiver was written
#define BIND_TEX_ATLAS_LIT          14  // rgba16f, rgb = E_ind (W/m^2), dilated into the gutters;
                                        // a = 1 surface, 0.5 dilated, 0 empty
// The back side (against the normal) of double-sided texels: the same as the three above.
// Single-sided texels leave them 0; scenes without double-sided materials have 1 x 1 ones.
#define BIND_TEX_VPL_POSITION       8   // rgba32f camera G-buffer: xyz = world position (m),
                                        // w = distance along the view axis (m), 0 = empty
#define BIND_TEX_VPL_NORMAL         9   // rgba16f camera G-buffer: xyz = unit normal facing
                                        // the eye, w = 1 where a surface is
#define BIND_TEX_VPL_GATHERED       10  // rgba32f, E_ind of each pixel's VPL subset (x tiles^2)
#define BIND_TEX_ATLAS_DIRECT_BACK  15
#define BIND_TEX_ATLAS_SUMS_BACK    16
#define BIND_TEX_ATLAS_LIT_BACK     17
#define BIND_TEX_ATLAS_IMPORTANCE   26  // rg32f, atlas.importance: how much of each texel's light
                                        // its receivers can receive, front (r) and back (g)
#define BIND_TEX_ATLAS_SURFACE_MASK 25  // r8ui, bit i set when neighbour i of the texel's 3x3
                                        // block (row order, the centre left out) lies on the
                                        // texel's own surface (atlas/surface_mask.frag)

// The temporal filter of the indirect irradiance (render/TemporalFilter.h).
#define BIND_TEX_TEMPORAL_CURRENT   18  // rgba16f, this frame's E_ind, a = view depth (m)
#define BIND_TEX_TEMPORAL_HISTORY   19  // rgba32f, the filter's previous output, same layout
#define BIND_TEX_TEMPORAL_HISTORY_NORMAL 20 // rgba16f, xyz = its surface normals, w = frames of
                                        // history behind each texel

// Trace reuse (gi/voxel/TraceReusePass.h): one pixel of each 2x2 block traced per frame.
#define BIND_TEX_REUSE_TRACED       21  // rgba16f, this frame's traced pixels: E_ind, a = view
                                        // depth (m), one texel per 2x2 block of the trace
#define BIND_TEX_REUSE_DEPTH        22  // depth32f, the surfaces of every pixel of the trace
#define BIND_TEX_REUSE_HISTORY      23  // rgba16f, the previous frame's result, E_ind + depth

// Image units (imageLoad/Store/atomics) of the voxel passes.
#define BIND_IMG_ATLAS_IMPORTANCE   0   // rg32f, written by atlas/sender_sampling's importance step
#define BIND_IMG_VOXEL_ALBEDO       0   // rgba16f, running average under the voxel's spinlock
#define BIND_IMG_VOXEL_NORMAL       1   // rgba8_snorm, running averages: xyz = normal, w = the
                                        // surface's offset from the voxel centre along it
                                        // (voxel sizes)
#define BIND_IMG_VOXEL_IRRADIANCE   2   // rgba16f, rgb = E summed over lights (W/m^2),
                                        // a = surface area in the voxel / voxel face area
#define BIND_IMG_VOXEL_HELPER       3   // rgba16f, rgb = the current light's mean E
                                        // (INJECT_FRAGMENT) or what a bounce gathered
#define BIND_IMG_VOXEL_LOCK         4   // r32ui, bit 0 = spinlock, bits 1..31 = fragment count
#define BIND_IMG_FILTER_TARGET      5   // rgba16f, filtered E_ind + view depth
#define BIND_IMG_VOXEL_PYRAMID_SOURCE 6 // rgba16f, pyramid mip m-1 read while mip m is built
#define BIND_IMG_VOXEL_GATHERED     6   // rgba16f, gi.bounces > 1: the indirect E x coverage the
                                        // voxel's own cones gathered (the pyramid source's
                                        // unit: no pass binds both)
#define BIND_IMG_VOXEL_PYRAMID      7   // rgba16f, pyramid mip m being built
#define BIND_IMG_VOXEL_FLUX_SUM     6   // r32ui (3v, v, v*l), INJECT_AREA: x-slab c = channel c
                                        // of the flux / voxel face area summed in fixed point
                                        // (voxel_flux_sum.glsl; only injection binds it)
#define BIND_IMG_VOXEL_DISTANCE_X   6   // r8ui (v^3), the empty-distance pass' distances along x
#define BIND_IMG_VOXEL_DISTANCE_XY  7   // r8ui (v^3), ... over x and y (the pyramid's units: no
                                        // pass binds both)
#define BIND_IMG_VOXEL_EDGE_FACES   5   // rgba8_snorm (2v, v, v), written by the edge-faces
                                        // pass alone (EdgeFacesPass.h)
#define BIND_IMG_VPL_TARGET         5   // the VPL gather's (rgba32f) or filter's (rgba16f) output
#define BIND_IMG_VPL_DEBUG_IDS      6   // r32ui, the VPL debug views: the key of the VPL drawn
                                        // over each pixel (VplDebugPass), 0 = none
#define BIND_IMG_VPL_DEBUG_TARGET   7   // rgba32f, a VPL debug view's image
#define BIND_IMG_VOXEL_DIRECTIONAL  5   // rgba16f (6v, v, v*l), voxel.anisotropic: while
                                        // voxelizing and injecting, per face f of a voxel
                                        // rgb = flux / face area of the surfaces seen from f,
                                        // a = their area projected onto f / face area; then
                                        // the directional voxels (the filter target's unit:
                                        // no pass binds both)
#define BIND_IMG_TEMPORAL_TARGET    0   // rgba32f, the filtered E_ind + view depth (no other
                                        // pass runs with it)
#define BIND_IMG_TEMPORAL_NORMAL    1   // rgba16f, the normals and history lengths it writes
#define BIND_IMG_REUSE_TARGET       0   // rgba16f, trace reuse's result (no other pass runs
                                        // with it)

// Faces of an anisotropic voxel: VOXEL_FACE_POS_X is the voxel as seen from +x (by a cone
// travelling towards -x), face f in x-slab f of the directional textures.
#define VOXEL_FACE_POS_X            0
#define VOXEL_FACE_NEG_X            1
#define VOXEL_FACE_POS_Y            2
#define VOXEL_FACE_NEG_Y            3
#define VOXEL_FACE_POS_Z            4
#define VOXEL_FACE_NEG_Z            5
#define VOXEL_FACES                 6

// VoxelUniforms.grid.z: isotropic or anisotropic voxels, whose light (the faces of the
// anisotropic voxels, and of the light pyramid above the coarsest level of either kind) a cone
// reads where it meets a surface as its own directions see those faces (voxel.light_read=cone)
// or as the surface met faces (voxel.light_read=surface).
#define VOXEL_KIND_ISOTROPIC        0
#define VOXEL_KIND_ANISOTROPIC      1
#define VOXEL_KIND_ANISOTROPIC_SURFACE_READ 2
#define VOXEL_KIND_ISOTROPIC_SURFACE_READ   3

#define VOXEL_MAX_LEVELS            8
#define VOXEL_VISIBILITY_MAX_STEPS  512 // voxels one segment of voxel_visibility.glsl walks at most
#define VOXEL_VISIBILITY_MAX_EDGES  2   // edge voxels per segment met at their two faces
#define INJECT_AREA                 0   // flux per fragment / surface area in the voxel
#define INJECT_FRAGMENT             1   // the thesis: mean over fragments, summed over lights
#define VOXEL_LOCAL_SIZE            8   // compute work groups are 8x8x8 (thesis 4.3.3.3)
#define VOXEL_FILTER_LOCAL_SIZE     8   // the indirect filter runs 8x8 texel groups
#define VOXEL_FILTER_MAX_RADIUS     8   // voxel.filter 4 at voxel.trace_scale 1, in texels
#define TEMPORAL_LOCAL_SIZE         8   // the temporal filter runs 8x8 texel groups
#define TRACE_REUSE_LOCAL_SIZE      8   // trace reuse runs 8x8 texel groups

#define BVH_MAX_LEAF_TRIANGLES      4   // triangles per leaf of the scene's BVH at most
#define ATLAS_SENDER_BLOCK          16  // texels per block of the sender table's row prefix sums
#define ATLAS_POOL_STRIDE           64  // sender points per stratum (a receiver uses one)
#define ATLAS_SENDER_LOCAL_SIZE     64  // work-group size of atlas/sender_sampling
#define ATLAS_VIEW_SAMPLES_PER_SIDE 16  // cells per side of the image whose surfaces weigh the
                                        // senders' draw (atlas.importance=view)
#define ATLAS_SURFACE_POINTS        1024 // points on the scene's triangles whose kernel weighs
                                        // the senders' draw (atlas.importance=surfaces)
#define SURFACE_POINT_UINTS         6   // uints per atlas::SurfacePoint
#define ATLAS_POSE_LOCAL_SIZE       64  // work-group size of atlas/follow_pose
#define SCENE_VERTEX_FLOATS         14  // floats per GpuScene vertex (scene::SceneVertex)
#define ATLAS_VERTEX_FLOATS         18  // floats per atlas vertex (atlas::GpuAtlasVertex)
#define ATLAS_VERTEX_UV_OFFSET      14  // the float at which its atlas coordinates start
#define ATLAS_ESTIMATOR_AREA        0   // L cos cos / r^2 x sample area: the rendering equation
#define ATLAS_ESTIMATOR_MERZ2010    1   // the thesis' eq. 9: L cos(theta_x) x 2 pi / N
#define ATLAS_VISIBILITY_NONE       0   // senders are never occluded (the thesis)
#define ATLAS_VISIBILITY_VOXEL      1   // ray march through the voxel occupancy
#define ATLAS_VISIBILITY_BVH        2   // rays through the scene's triangles (common/bvh.glsl)
#define ATLAS_IMPORTANCE_POWER      0   // senders drawn by the power they send alone
#define ATLAS_IMPORTANCE_VIEW       1   // x what the surfaces the camera sees can receive of it
#define ATLAS_IMPORTANCE_SURFACES   2   // x what the scene's surfaces can receive of it
#define ATLAS_VIEW_DIRECT           0   // debug views of the atlas layers, seen from the camera
#define ATLAS_VIEW_NORMAL           1
#define ATLAS_VIEW_POSITION         2
#define ATLAS_VIEW_ALBEDO           3
#define ATLAS_VIEW_INDIRECT         4
#define ATLAS_VIEW_CHARTS           5

#define VPL_LOCAL_SIZE              8   // the VPL gather and filter run 8x8 pixel groups
#define VPL_TILE                    4   // interleaved sampling: 4x4 pixels, 16 VPL subsets
#define VPL_VISIBILITY_NONE         0   // VPLs are never occluded
#define VPL_VISIBILITY_CASCADE      1   // segment march through the voxel occupancy
#define VPL_BOUNCE_LOCAL_SIZE       64  // the VPL bounce rays run 64 per work group
#define VPL_VISIBILITY_SVO          2   // restart march through the sparse voxel octree
#define VPL_VISIBILITY_BVH          3   // rays through the scene's triangles (common/bvh.glsl)

// The sparse voxel octree (gi/vpl/SparseVoxelOctree.h, common/svo.glsl).
#define SVO_NODE_FLAG               0x80000000u   // the node's cube holds geometry
#define SVO_CHILD_MASK              0x7fffffffu   // first of its 8 children, 0 = none
#define SVO_COORD_BITS              10            // leaf coordinates packed 10 bits per axis
#define SVO_MAX_DEPTH               10            // 1024 leaves per side at most
#define SVO_VISIBILITY_MAX_STEPS    2048          // restarts of one svo_visibility.glsl segment
#define SVO_LOCAL_SIZE              64            // build passes run 64 invocations a group
#define SVO_PASS_FLAG               0             // build pass: flag the nodes of a level
#define SVO_PASS_ALLOCATE           1             // build pass: give flagged nodes 8 children
#define SVO_PASS_ADVANCE            2             // build pass: the next level's range
#define VPL_GATHER_IRRADIANCE       0   // VplUniforms.counts.w: the gather sums E_ind
#define VPL_GATHER_VISIBLE_FRACTION 1   // ... or writes the mean visibility of the VPLs that
                                        // face the surface (the vpl-visibility debug view)
#define VPL_DEBUG_POINTS            0   // VPLs as discs coloured by flux over grey surfaces
#define VPL_DEBUG_SUBSET            1   // ... one pixel class's VPLs in colour, the rest grey
#define VPL_DEBUG_VISIBILITY        2   // the mean visibility of the facing VPLs, grey

// Vertex attribute locations of the scene's vertex buffer.
#define ATTR_POSITION               0   // vec3, world space, metres
#define ATTR_NORMAL                 1   // vec3, world space, unit length
#define ATTR_TEXCOORD0              2   // vec2
#define ATTR_TEXCOORD1              3   // vec2
#define ATTR_COLOR                  4   // vec4, linear RGBA (COLOR_0, white when absent)
#define ATTR_ATLAS_UV               5   // vec2, atlas coordinate in [0,1]^2 (atlas geometry only)
#define ATTR_ATLAS_INFO             6   // vec2, x = chart index, y = 1 if double-sided

// Uniform locations set per draw or per view.
#define LOC_DRAW_MATERIAL           0   // int, index into GpuMaterial[]
#define LOC_SHADOW_VIEW_PROJECTION  1   // mat4, world -> clip of the shadow view being drawn
#define LOC_SHADOW_LIGHT_POSITION   2   // vec4, xyz = point light position, w = far distance
                                        // (0 for spot/directional: hardware depth is used)
#define LOC_PRESENT_SCALE           3   // float, radiance multiplier undoing the pre-exposure
#define LOC_FORWARD_INDIRECT_SIZE   4   // vec2, texels of the indirect texture at
                                        // BIND_TEX_INDIRECT; (0, 0) = no indirect light
#define LOC_VOXEL_LEVEL             5   // int, cascade level (propagation, debug view),
                                        // pyramid mip being written by this dispatch, or the
                                        // axis the empty-distance pass runs along
#define LOC_VOXEL_DEBUG_VIEW        6   // int, 0 albedo, 1 irradiance, 2 normal
#define LOC_INJECT_VIEW_PROJECTION  7   // mat4, world -> clip of the light view being injected
#define LOC_INJECT_AXIS             8   // vec4, xyz = unit forward axis of the light view,
                                        // w = 1 for an orthographic view
#define LOC_INJECT_FOOTPRINT        9   // float, one pixel of the light view: sr on the axis
                                        // (perspective) or m^2 (orthographic)
#define LOC_INJECT_LIGHT            10  // int, index into GpuLight[] of the injected light
#define LOC_INJECT_FLUX_SUM         37  // vec2, x = fixed-point units per unit of flux / voxel
                                        // face area (fluxSumScale, InjectPass.h), y = the
                                        // light view's ordinal (seeds the rounding)
#define LOC_ATLAS_NEAR_RANGE        38  // ivec4: the near field's directions [x, y) this draw
                                        // adds, z = nodes a ray's walk may visit
#define LOC_PRESENT_EXPOSURE        11  // float, display exposure: 2^EV or the auto exposure
#define LOC_PRESENT_CURVE           12  // int, TONE_CURVE_NONE or TONE_CURVE_FILMIC
#define LOC_LINESPACE_LEVEL         13  // int, N-tree level an occupancy reduction writes
#define LOC_LINESPACE_COUNT         14  // uint, triangles (voxelization) or nodes (line spaces)
#define LOC_LINESPACE_FIRST         15  // uint, first node of this line-space dispatch
#define LOC_RSM_VIEW_PROJECTION     16  // mat4, world -> clip of the reflective shadow map view
#define LOC_RSM_AXIS                17  // vec4, xyz = unit forward axis, w = 1 orthographic
#define LOC_RSM_FOOTPRINT           18  // float, one RSM pixel: sr on the axis (perspective)
                                        // or m^2 (orthographic)
#define LOC_RSM_LIGHT               19  // int, index into GpuLight[] of the light drawn
#define LOC_TEMPORAL_PREVIOUS_VIEW_PROJECTION 20 // mat4, world -> clip of the previous frame
#define LOC_TEMPORAL_PREVIOUS_VIEW  21  // mat4, world -> camera of the previous frame
#define LOC_TEMPORAL_PARAMETERS     22  // vec4, x = blend weight of the new frame, y = 1 when
                                        // a history exists, z = 1 to clamp the history
#define LOC_VPL_BOUNCE_COUNTS       23  // ivec2, x = first-generation VPLs, y = bounce rays
#define LOC_CONE_TRACE_OFFSET       24  // vec2, NDC shift that puts a pixel of a strided trace
                                        // on the centre of the pixel it stands for
#define LOC_CONE_TRACE_PATTERN      25  // ivec3, x = stride s, yz = which pixel of each s x s
                                        // block this trace covers (1, 0, 0: every pixel)
#define LOC_REUSE_PREVIOUS_VIEW_PROJECTION 26 // mat4, world -> clip of the previous frame
#define LOC_REUSE_PREVIOUS_VIEW     27  // mat4, world -> camera of the previous frame
#define LOC_REUSE_PHASE             28  // ivec4, xy = the pixel of each 2x2 block traced this
                                        // frame, z = 1 when a history exists, w = the stride
                                        // traced (1: every pixel)
#define LOC_SVO_LEVEL               29  // int, octree level a build pass works on (root = 0)
#define LOC_FORWARD_INDIRECT_SPECULAR 30 // int, 1: BIND_TEX_INDIRECT_SPECULAR holds voxel GI's
                                        // specular cone (material.model=gltf)
#define LOC_VPL_DEBUG_HIGHLIGHT     31  // int, the pixel class (VPL subset) whose VPLs the
                                        // debug splat highlights; -1 = every VPL
#define LOC_VPL_DEBUG_RADIUS        32  // int, radius of a highlighted VPL's disc (pixels)
#define LOC_VPL_DEBUG_VIEW          33  // int, VPL_DEBUG_* the compose pass draws
#define LOC_ATLAS_GATHER_RANGE      34  // ivec4, xy = the samples [x, y) of the set and zw = the
                                        // sky directions [z, w) this gather draw adds
#define LOC_VPL_GATHER_RANGE        35  // ivec3, xy = the VPLs [x, y) of each pixel's subset this
                                        // dispatch adds, z = 1 on the last dispatch
#define LOC_RSM_GLTF                36  // int, 1 when surfaces reflect with the glTF BRDF's
                                        // albedos (reflectance.glsl)

// llvmpipe (Mesa's gallivm) ends every loop of a shader invocation, silently, once all of its
// loops together have run this many iterations (LP_MAX_TGSI_LOOP_ITERATIONS): a gather whose
// loops run longer drops the rest of its samples. Passes whose loops can run longer split
// their work into draws or dispatches that stay within it (gl/LoopBudget.h).
#define SHADER_LOOP_ITERATIONS      65535

// Tone curves of the displayed image (core/ToneMap.h, common/tonemap.glsl).
#define TONE_CURVE_NONE             0   // clamp to [0, 1]
#define TONE_CURVE_FILMIC           1   // ACES fitted (Narkowicz 2015), the constants below
// f(x) = x (a x + b) / (x (c x + d) + e), clamped to [0, 1]: Krzysztof Narkowicz, "ACES
// Filmic Tone Mapping Curve" (2015), a fit of the ACES reference rendering transform.
#define TONE_ACES_A                 2.51
#define TONE_ACES_B                 0.03
#define TONE_ACES_C                 2.43
#define TONE_ACES_D                 0.59
#define TONE_ACES_E                 0.14

#define LIGHT_POINT                 0
#define LIGHT_SPOT                  1
#define LIGHT_DIRECTIONAL           2
#define LIGHT_AREA                  3   // emitting triangles (GpuEmitter), shadowed from their centre
#define LIGHT_SKY                   4   // constant radiance from every unblocked direction

// Which radiance component a frame writes (--output).
#define OUTPUT_FINAL                0
#define OUTPUT_DIRECT               1
#define OUTPUT_INDIRECT             2

// shadow.method: how the direct light the camera sees is shadowed.
#define SHADOW_METHOD_SHADOWMAP     0   // shadow maps (area lights: from their centre)
#define SHADOW_METHOD_BVH           1   // rays through the scene's BVH (GpuBvh)
#define SHADOW_METHOD_LINESPACE     2   // rays through an N-tree's line spaces (linespace.glsl)
#define SHADOW_METHOD_VOXEL         3   // a cone through the voxel occupancy (voxel_shadow_cone.glsl)
#define SHADOW_METHOD_COUNT         4

#define LINESPACE_EMPTY             0xFFFFFFFFu // a child without geometry
#define LINESPACE_LOCAL_SIZE        64  // invocations per group of the build's compute passes

#define SHADOW_NONE                 0
#define SHADOW_2D                   1
#define SHADOW_CUBE                 2

// Kinds of material texture a scene has (FRAME_MATERIAL_TEXTURES, GpuScene::textureKinds).
#define MATERIAL_TEXTURES_BASE_COLOR 1
#define MATERIAL_TEXTURES_EMISSIVE  2

// GpuMaterial.flags.y bits.
#define MATERIAL_EMISSIVE_TEXTURE   1   // the emission is multiplied by the emissive texture
#define MATERIAL_EMITS_AS_LIGHT     2   // its emission is an area light's (LIGHT_AREA): passes
                                        // that shade with lights must not count it again

// FrameUniforms.shading.z: the material model (core/Settings.h MaterialModel).
#define SHADING_LAMBERT             0   // Lambertian only (material.specular = 0)
#define SHADING_PHONG               1   // Lambertian + Blinn-Phong highlight in direct light
#define SHADING_GLTF                2   // glTF metallic-roughness (shaders/common/brdf.glsl)

#define ALPHA_OPAQUE                0
#define ALPHA_MASK                  1

#ifdef __cplusplus
namespace gi::shader {
#endif

// FrameUniforms.counts.w: how the forward pass upsamples a GI technique's indirect texture
// (voxel.upsample_depth, voxel.upsample_plane).
#define UPSAMPLE_BILINEAR           0
#define UPSAMPLE_DEPTH              1   // weighted by view depth
#define UPSAMPLE_DEPTH_PLANE        2   // and by the distance from the pixel's plane

struct FrameUniforms {                  // std140
    mat4 viewProjection;                // world -> clip
    mat4 view;                          // world -> camera
    vec4 cameraPosition;                // xyz = world-space eye (m), w = unused
    vec4 shading;                       // x = specular strength ks, y = Blinn-Phong exponent,
                                        // z = SHADING_* model, w = 1 to apply shadows
    mat4 inverseViewProjection;         // clip -> world, for per-pixel rays
    vec4 screen;                        // xy = output size (pixels), zw = unused
    ivec4 counts;                       // x = number of lights, y = OUTPUT_* component to
                                        // write, z = unused, w = UPSAMPLE_* of the
                                        // indirect texture
    vec4 sky;                           // rgb = radiance of the sky lights together
                                        // (W/(m^2 sr)), seen where a cone escapes; w = unused
    vec4 shadowing;                     // x = SHADOW_METHOD_*, y = shadow rays per area light,
                                        // z = shadow-ray origin offset along the normal (m),
                                        // w = unused
};

struct GpuLight {                       // std430
    vec4 positionAndType;               // xyz = world position (m; area: the emitters'
                                        // centre), w = LIGHT_* as float
    vec4 directionAndRange;             // xyz = unit direction light travels, w = range (0 = inf)
    vec4 radiantIntensity;              // rgb = colour x intensity (W/sr, or W/m^2 for
                                        // directional; radiance W/(m^2 sr) for the sky),
                                        // w = unused
    vec4 spotCone;                      // x = cos(inner), y = cos(outer), z = smallest
                                        // squared distance 1/r^2 uses (m^2), w = unused;
                                        // area: x = first GpuEmitter, y = their count,
                                        // w = radius of the sphere about the centre that
                                        // holds every emitter (m)
};

struct GpuEmitter {                     // std430, one triangle of an area light
    vec4 p0;                            // xyz = corner (m), counter-clockwise seen from the
    vec4 p1;                            // front; w = unused
    vec4 p2;
    vec4 radiance;                      // rgb = emitted radiance (W/(m^2 sr)), w = 1 if it
                                        // emits from both sides
};

struct GpuLineSpaceHeader {             // std430, the start of BIND_SSBO_LINESPACE_NODES
    vec4 root;                          // xyz = the root cube's lowest corner (m), w = its edge
    ivec4 shape;                        // x = N, y = depth d, z = uints per line space,
                                        // w = nodes (0: no geometry, nothing is occluded)
};

struct GpuMaterial {                    // std430
    vec4 baseColorFactor;               // linear RGBA
    vec4 emissiveAndCutoff;             // rgb = emissive factor (linear), w = alpha cutoff
    ivec4 flags;                        // x = has base-colour texture, y = MATERIAL_* bits,
                                        // z = ALPHA_* mode, w = base-colour texcoord set (0/1)
    vec4 metallicRoughness;             // x = metallic, y = perceptual roughness (glTF
                                        // factors, material.model=gltf only), zw = unused
};

struct VoxelUniforms {                  // std140
    vec4 levelOrigin[VOXEL_MAX_LEVELS]; // xyz = world-space min corner of level k (m),
                                        // w = voxel edge length of level k (m)
    ivec4 grid;                         // x = resolution v, y = level count l, z = the
                                        // voxels' kind (VOXEL_KIND_*: voxel.anisotropic and
                                        // voxel.light_read), w = the widest pyramid mip cone
                                        // tracing reads (-1 = all)
    vec4 trace;                         // x = cone half-angle tan, y = max distance (m),
                                        // z = step factor (x cone diameter), w = 1 to apply
                                        // the thesis' 1/(1+d^2) falloff
    vec4 cones;                         // x = weight of the central cone, y = pixel classes
                                        // sharing the rings' cones (1 or 2), z = 1 when the
                                        // dither moves the rings in elevation
                                        // (voxel.jitter_elevation), w = voxels between a
                                        // cone's origin and the start of its walk on a
                                        // one-level volume (voxel.walk_start) (ConeSet.h)
    vec4 coneRings[3];                  // per ring: x = cones (0: no ring), y = sin^2 of their
                                        // angle from the normal, z = how far in sin^2 the
                                        // dither moves them up and down, w = each cone's weight
    vec4 injection;                     // x = irradiance threshold (W/m^2) below which a
                                        // fragment is discarded, yzw = unused
    vec4 modes;                         // x = INJECT_* weighting, y = 1 when surfaces
                                        // reflect with the glTF BRDF's albedos
                                        // (voxel_reflectance.glsl),
                                        // z = 1 for max-axis coverage in
                                        // propagation, w = 1 when cone tracing takes a
                                        // coarser level's unit normal for one plane
    vec4 smoothing;                     // x = filter radius in trace texels (0 = off),
                                        // y = the cone ring's per-pixel turn: 8 x turns
                                        // per axis (2 or 4) + pixels per cell and axis
                                        // (RingDither.h), 0 = no jitter, z = log2
                                        // of the texel width of the light pyramid mip a cone
                                        // reads, in cone diameters (voxel.footprint),
                                        // w = finest voxels between a surface and its
                                        // cones' origin (voxel.cone_offset)
    vec4 raster;                        // voxelization: x = 1 to rasterize each level over
                                        // its own extent, 0 for one raster over the
                                        // coarsest; y = 1 / voxel.multiplier^2, a raster
                                        // pixel's area in face areas of the voxels of the
                                        // level rasterized; z = 1 to sum the surfaces'
                                        // area projected onto the x, y and z faces into
                                        // irradiance.rgb (the visibility occupancy, which
                                        // no light is injected into); w = unused
};

struct GpuShadow {                      // std430, one per light
    mat4 worldToShadow;                 // SHADOW_2D: world -> shadow clip space
    vec4 params;                        // x = SHADOW_* kind, y = layer in its array,
                                        // z = far distance (m) for cube maps,
                                        // w = world-space size of one texel at 1 m distance
                                        //     (perspective) or everywhere (orthographic)
    vec4 bias;                          // x = normal offset in texels, y = PCF radius in
                                        //     texels, z = 1 if orthographic, w = unused
};

struct GpuVpl {                         // std430, one virtual point light
    vec4 position;                      // xyz = world position (m), w = unused
    vec4 normal;                        // xyz = unit normal of its lit side, w = unused
    vec4 flux;                          // rgb = flux it reflects (W, pre-exposed), w = the
                                        // surface it stands for (m^2; 0 = unknown: the
                                        // second generation's)
};

struct VplUniforms {                    // std140
    ivec4 counts;                       // x = VPLs, y = tile edge (VPL_TILE, or 1 without
                                        // interleaving), z = VPL_VISIBILITY_*,
                                        // w = VPL_GATHER_* (what the gather writes)
    vec4 gather;                        // x = clamp B of 1 / max(B, r^2) (m^2), y = the subset
                                        // scale (tiles^2), z = filter depth tolerance
                                        // (fraction of the depth), w = filter normal cosine
    vec4 rays;                          // x = how far vpl.visibility=bvh's rays start off both
                                        // surfaces (m), y = B per m^2 a VPL stands for
                                        // where that exceeds gather.x (vpl.clamp = 0;
                                        // 0 = gather.x for every VPL),
                                        // zw = unused
};

struct SvoUniforms {                    // std140
    vec4 cube;                          // xyz = the octree cube's lowest corner (m), w = leaf
                                        // voxel edge (m)
    ivec4 shape;                        // x = leaves per side (2^depth), y = depth (levels
                                        // below the root), z = fragment raster size (pixels),
                                        // w = node capacity of the pool
    vec4 march;                         // x = the ends' push off their surfaces, y = the
                                        // segment's shrink at both ends, z = epsilon past a
                                        // node's exit (all in leaf voxels), w = unused
};

struct SvoBuildState {                  // std430, the octree build's bookkeeping on the GPU
    ivec4 dispatch;                     // xyz = DispatchIndirectCommand over the level being
                                        // allocated, w = unused
    ivec4 counts;                       // x = nodes allocated (the atomic counter), y = 1 if
                                        // an allocation did not fit the pool, zw = unused
    int levelStart[SVO_MAX_DEPTH + 2];  // first node of each level; levelStart[l + 1] ends l
};

struct AtlasUniforms {                  // std140
    ivec4 size;                         // x = atlas resolution R (texels per side), y = samples
                                        // N in the current set, z = ATLAS_ESTIMATOR_*,
                                        // w = ATLAS_VIEW_* shown by the debug view
    vec4 sampling;                      // xy = Cranley-Patterson offset of the current set,
                                        // z = estimator constant (area: the smallest r^2 its
                                        // 1/r^2 uses, (2 texel edges)^2 in m^2; merz2010:
                                        // 2 pi), w = 1 / samples accumulated
    vec4 dilation;                      // x = dilation radius (texels), y = 1 if the back-side
                                        // layers exist (double-sided materials), z = 1 with
                                        // atlas.filter, w = unused
    vec4 sky;                           // rgb = radiance of the sky lights together
                                        // (W/(m^2 sr)), w = sky directions per receiver and set
    vec4 importance;                    // x = the share of the mean importance every lit texel
                                        // keeps, 0 = senders drawn by power alone (I = 1);
                                        // y = cells of BIND_SSBO_ATLAS_RECEIVERS; z = 1 when
                                        // every surface sends (gi.bounces > 1), 0 when only
                                        // directly lit texels do; w = the smallest r^2 (m^2)
                                        // the importance's 1/r^2 uses
    vec4 nearField;                     // x = the near field's directions per receiver side
                                        // and set (atlas.near_rays, 0 = none), y = its reach
                                        // squared (m^2): senders nearer the receiver count
                                        // through its rays, not the area estimator's draw
};

#ifdef __cplusplus
} // namespace gi::shader
#endif

#endif
