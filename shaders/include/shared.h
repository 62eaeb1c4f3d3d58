// shared.h — the one header read by both C++ and GLSL.
//
// Binding points, limits and the std140/std430 structs that cross the CPU/GPU boundary live
// here and nowhere else. C++ includes it as <shared.h> (namespace lit::gpu) with static_asserts
// on every struct size; GLSL gets it through the shader loader's #include.
// Every struct uses only vec4/ivec4/mat4 members so std140 and std430 lay them out like C++.
#ifndef LIT_SHARED_H
#define LIT_SHARED_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace lit::gpu {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
#endif

// ---- Uniform buffer binding points -------------------------------------------------------
#define LIT_UBO_FRAME 0        // FrameUniforms: camera, viewport, exposure, view mode
#define LIT_UBO_SHADOW_PASS 1  // ShadowPassUniforms: the light view being rendered
#define LIT_UBO_VOXEL 2        // VoxelUniforms: where the voxel volume is and how to trace it
#define LIT_UBO_OUTER_VOXEL 3  // VoxelUniforms of the next volume out, for a near level's rays (LIT_NEAR_LEVEL)
#define LIT_UBO_FAR_VOXEL 4    // VoxelUniforms of the scene's volume, for a near level's rays (LIT_NEAR_LEVEL)
#define LIT_MAX_NEAR_LEVELS 5  // near levels at most (kMaxNearLevels)
#define LIT_UBO_NEAR_VOXEL_FIRST 5  // VoxelUniforms of near level k at FIRST + k, for the pixels' gather (LIT_NEAR_GATHER)
#define LIT_UBO_SHADOW_CASCADES (LIT_UBO_NEAR_VOXEL_FIRST + LIT_MAX_NEAR_LEVELS)  // ShadowCascadeUniforms

// ---- Shader storage buffer binding points ------------------------------------------------
#define LIT_SSBO_LIGHTS 0      // GpuLight[lightCount]
#define LIT_SSBO_MATERIALS 1   // GpuMaterial[materialCount]
#define LIT_SSBO_LUMINANCE_HISTOGRAM 2  // uint[LIT_EXPOSURE_BINS]: auto exposure's log-luminance histogram
#define LIT_SSBO_EXPOSURE 3             // vec4: x multiplier, y log2 multiplier (stops), z metered mean log2 luminance, w valid

// ---- Uniform locations of per-draw values (layout(location = N) uniform ...) ----------------
#define LIT_LOC_MODEL 0            // mat4 object → world
#define LIT_LOC_NORMAL_MATRIX 1    // mat4 inverse transpose of the model matrix
#define LIT_LOC_MATERIAL 2         // int index into GpuMaterial[]
#define LIT_LOC_NODE_ID 3          // uint node index + 1 the G-buffer writes to its ID target (0 = background)
#define LIT_LOC_UV_TRANSFORMS 4    // vec4[2 × LIT_MATERIAL_SLOTS] at 4 .. 31: texture transforms (material.glsl)
#define LIT_LOC_PRIMITIVE 32       // uint primitive index within the node's mesh the G-buffer writes beside the node ID
#define LIT_LOC_PREVIOUS_MODEL 33  // mat4 object → world in the last frame (the G-buffer's motion target)

// ---- Texture units -----------------------------------------------------------------------
// Material textures (G-buffer, shadow alpha test, voxelization).
#define LIT_TEX_BASE_COLOR 0
#define LIT_TEX_METALLIC_ROUGHNESS 1
#define LIT_TEX_NORMAL 2
#define LIT_TEX_EMISSIVE 3
#define LIT_TEX_OCCLUSION 4
// G-buffer read by the lighting passes.
#define LIT_TEX_GBUFFER_ALBEDO 5     // rgb albedo (linear), a occlusion
#define LIT_TEX_GBUFFER_NORMAL 6     // rgb world normal, a unused
#define LIT_TEX_GBUFFER_MATERIAL 7   // r roughness, g metalness, b clear-coat texel, a coat-roughness texel
#define LIT_TEX_GBUFFER_EMISSIVE 8   // rgb emitted radiance (W/(sr·m²))
#define LIT_TEX_GBUFFER_DEPTH 9      // window-space depth [0,1]
// Shadow maps.
#define LIT_TEX_SHADOW_2D 10         // sampler2DArrayShadow: directional and spot lights
#define LIT_TEX_SHADOW_CUBE 11       // samplerCubeArrayShadow: point lights
// Post processing and debug views.
#define LIT_TEX_HDR_INPUT 12
#define LIT_TEX_TERM_DIRECT_DIFFUSE 13
#define LIT_TEX_TERM_DIRECT_SPECULAR 14
#define LIT_TEX_TERM_INDIRECT_DIFFUSE 15
#define LIT_TEX_TERM_INDIRECT_SPECULAR 16
#define LIT_TEX_DEBUG_INPUT 17       // whatever a debug view shows (shadow map layer, ...)
#define LIT_TEX_TAA_HISTORY 17       // TemporalAntialiasPass: the last frames' resolved image (after the composite)
#define LIT_TEX_TAA_HISTORY_DEPTH \
    13  // ... and the depth it was drawn with (the unit of a lighting term, which the pass does not bind)
// The voxel-levels view: each running volume's radiance, finest first (its pass binds nothing else
// on the material units it reuses).
#define LIT_TEX_DEBUG_LEVELS_FIRST 0
// Voxel volumes (voxel cone tracing).
#define LIT_TEX_VOXEL_RADIANCE 18
#define LIT_TEX_VOXEL_ALBEDO 19
#define LIT_TEX_VOXEL_EMISSION 21
// Two-sided voxels' direct light by side (VoxelVolume::sides, RG32UI; voxel.glsl, "Sides"): the
// voxel rays read it where they end (bounce.comp.glsl).
#define LIT_TEX_VOXEL_SIDES 20
// Cone tracing (ConeTracePass): the GGX lobe's directional albedo table, RG16F, x = n·v,
// y = roughness, E = F0·r + g (cone.glsl, specularAlbedo).
#define LIT_TEX_SPECULAR_ALBEDO 22
#define LIT_SPECULAR_ALBEDO_SIZE 32    // texels per side of that table
// The voxelizer's table of that lobe's hemispherical mean (Ā, B̄) at roughness j/(size − 1): a
// uniform array (scene/SpecularMeanAlbedo.h).
#define LIT_SPECULAR_MEAN_ALBEDO_SIZE 32
// The G-buffer's RGBA32UI IDs: r node index + 1 (0 = background), g the primitive within the
// node's mesh, b the material index (the lighting passes read its table, gbuffer.glsl).
#define LIT_TEX_GBUFFER_ID 23
#define LIT_SSBO_OUTLINE_CLASSES 4      // uint per node ID (index + 1): 0 not outlined, 1 selected, 2 active (overlay_outline.frag.glsl)
#define LIT_OUTLINE_RADIUS 2           // selection outline width (pixels outside the silhouette)
#define LIT_HIDDEN_LINE_OPACITY 0.25   // opacity multiplier of depth-tested lines where the scene hides them
// Reduced-resolution indirect lighting (ConeTracePass → IndirectResolvePass, docs/GI.md).
#define LIT_TEX_INDIRECT_LOW_PACKED 24    // RGBA32UI: irradiance/π and ⟨L⟩ of each block's traced pixel (indirect.glsl)
#define LIT_TEX_INDIRECT_LOW_GUIDE 25     // RGBA32UI: that pixel's world position and normal
#define LIT_TEX_HISTORY_DIFFUSE 26        // accumulated irradiance/π, a = frames accumulated
#define LIT_TEX_HISTORY_SPECULAR 27       // accumulated ⟨L⟩, a = frames accumulated
#define LIT_TEX_HISTORY_GUIDE 28          // last frame's world normal (xyz) and clip w (m; 0 = background)
#define LIT_DIFFUSE_ROTATION_STEPS 8      // temporal: the side cones turn by 72°/8 per frame (8-frame cycle)

// Sky (sky.glsl, scene/Sky.h): an equirectangular radiance image, RGB32F, row 0 = straight up.
#define LIT_TEX_SKY 24

// Anisotropic radiance volumes (VoxelVolume::directional, levels 1.. of the radiance volume as
// seen by a cone travelling along +X, −X, +Y, −Y, +Z, −Z; one volume per axis holds both of its
// faces): units FIRST .. FIRST + 2 = 29..31, past the history units so no pass has to rebind what another left bound. Unit numbers only
// have to stay below GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS (Capabilities.cpp asks for LIT_TEX_UNIT_COUNT).
#define LIT_TEX_VOXEL_DIRECTIONAL_FIRST 29
#define LIT_VOXEL_FACE_COUNT 6
#define LIT_VOXEL_AXIS_COUNT 3  // directional volumes: one per axis, holding its two faces
// Voxel irradiance (the cached GI mode, GiSettings::voxelIrradiance()). The filter reads
// the traced one: N × N × 2N in the radiance volume's format, the occupied voxels' irradiance/π on
// the side of their averaged normal (z < N) and the other (z + N, otherSideTexel in voxel.glsl).
// The cone passes read the filtered one: N³ RGBA32UI gather texels (packGatherTexel, voxel.glsl).
#define LIT_TEX_VOXEL_IRRADIANCE 32
// The lighting passes with material layers: E_s(n·v, sheen roughness), R32F, the sheen lobe's
// directional albedo (scene/SheenAlbedo.h, texel centres at (i + ½)/size).
#define LIT_TEX_SHEEN_ALBEDO 33
// Transmissive sheets in the shadow maps (ShadowPass): per layer, rgb the product of the
// transmittances of the sheets between the light and the nearest opaque surface, a the nearest
// sheet's linear depth (0 at the near plane, 1 at the far plane).
#define LIT_TEX_SHADOW_SHEETS 34
#define LIT_TEX_SHADOW_SHEETS_CUBE 35  // the same per cube face of a point light (RGBA16F cube array)
// The cached mode's near levels (docs/GI.md, "Near levels"): a near level's voxel rays continue in
// the next volume out, then the scene volume (LIT_NEAR_LEVEL: their radiance, normals and surface
// points); the pixels gather near level k's gather texels from FIRST + k (LIT_NEAR_GATHER).
#define LIT_TEX_OUTER_RADIANCE 36
#define LIT_TEX_FAR_RADIANCE 37
#define LIT_TEX_OUTER_NORMAL 38   // the next volume out's averaged normals and surface points (r32ui)
#define LIT_TEX_OUTER_SURFACE 39
#define LIT_TEX_FAR_NORMAL 40     // the scene volume's
#define LIT_TEX_FAR_SURFACE 41
#define LIT_TEX_NEAR_IRRADIANCE_FIRST 42
// The camera's shadow cascades of the directional lights (ShadowPass::executeCascades): cascade c
// of cascaded light k at layer k × cascades + c (sampler2DArrayShadow; GpuShadowCascade::params.z).
#define LIT_TEX_SHADOW_CASCADES (LIT_TEX_NEAR_IRRADIANCE_FIRST + LIT_MAX_NEAR_LEVELS)
// KHR_materials_transmission's transmissionTexture (sheets and their shadows; material.glsl).
#define LIT_TEX_TRANSMISSION (LIT_TEX_SHADOW_CASCADES + 1)
// The layers' textures (Material::clearcoatTexture ..; material.glsl materialLayerTexels), in the
// order of their material slots.
#define LIT_TEX_CLEARCOAT (LIT_TEX_TRANSMISSION + 1)
#define LIT_TEX_CLEARCOAT_ROUGHNESS (LIT_TEX_TRANSMISSION + 2)
#define LIT_TEX_SPECULAR (LIT_TEX_TRANSMISSION + 3)
#define LIT_TEX_SPECULAR_COLOR (LIT_TEX_TRANSMISSION + 4)
#define LIT_TEX_SHEEN_COLOR (LIT_TEX_TRANSMISSION + 5)
#define LIT_TEX_SHEEN_ROUGHNESS (LIT_TEX_TRANSMISSION + 6)
#define LIT_TEX_CLEARCOAT_NORMAL (LIT_TEX_TRANSMISSION + 7)
// KHR_materials_volume's thicknessTexture (sheets and their shadows; material.glsl
// materialVolumeTransmittance).
#define LIT_TEX_THICKNESS (LIT_TEX_TRANSMISSION + 8)
// The G-buffer's RGBA32UI layer texels (gbuffer.glsl): r the specular colour and specular texels,
// g the sheen colour and sheen-roughness texels, each packUnorm4x8(rgb, a), b the clear coat's
// world normal (octahedral, packSnorm2x16), a unused. Written and read only for materials with
// such textures or a coat normal of its own (GpuMaterial::layerTextures).
#define LIT_TEX_GBUFFER_LAYERS (LIT_TEX_TRANSMISSION + 9)
// The lit image before the sheets, which a refracting volume's front face samples where its bent
// path leaves it (SheetPass, sheet.frag.glsl).
#define LIT_TEX_SHEET_BEHIND (LIT_TEX_TRANSMISSION + 10)
#define LIT_TEX_SHEET_BEHIND_DEPTH (LIT_TEX_TRANSMISSION + 11)  // and its depth (window space)
// The G-buffer's motion target (GBufferPass::motion): each point's world position minus where it
// was in the last frame, in frames where nodes moved (TemporalAntialiasPass).
#define LIT_TEX_GBUFFER_MOTION (LIT_TEX_SHEET_BEHIND_DEPTH + 1)
#define LIT_TEX_UNIT_COUNT (LIT_TEX_GBUFFER_MOTION + 1)  // units 0 .. this − 1 are bound (Capabilities.cpp)

// ---- Image units (image load/store) ------------------------------------------------------
#define LIT_IMG_VOXEL_ALBEDO 0
#define LIT_IMG_VOXEL_NORMAL 1
#define LIT_IMG_VOXEL_EMISSION 2
#define LIT_IMG_VOXEL_RADIANCE 3
#define LIT_IMG_MIP_SOURCE 4
#define LIT_IMG_MIP_DEST 5
// Mipmap pass (MipmapPass): one dispatch writes up to three levels, k+1 at LIT_IMG_MIP_DEST,
// k+2 and k+3 at these. Units 4..7 stay below GL 4.5's guaranteed minimum of 8 image units.
#define LIT_IMG_MIP_DEST2 6
#define LIT_IMG_MIP_DEST3 7
// Multiple bounces (BouncePass): the direct radiance read, the next bounce written.
#define LIT_IMG_VOXEL_DIRECT 4
#define LIT_IMG_VOXEL_BOUNCE 5
// The light a bounce's voxel rays take where they end (bounce.comp.glsl): the direct volume for the
// second bounce, level 0 of the radiance volume (the bounce before) for later ones.
#define LIT_IMG_VOXEL_RAY_SOURCE 6
// Where in each voxel its surface lies (VoxelVolume::surface): the voxelization's running average of
// a point of each fragment's plane in the voxel, in [0,1]³ of the voxel; the voxel rays end on that
// plane (bounce.comp.glsl). Unit 7 is the mipmap pass's third destination, never bound with it.
#define LIT_IMG_VOXEL_SURFACE 7
// A bounce's change from the one before (VoxelVolume::change): written by the bounce copy, read by
// the later bounces' voxel rays. Unit 2 is the emission volume's, which neither pass binds.
#define LIT_IMG_VOXEL_CHANGE 2
// The injection writes the two-sided voxels' split of their direct light by side
// (VoxelVolume::sides). Unit 5 is the bounce volume's, which the injection does not bind.
#define LIT_IMG_VOXEL_SIDES 5

// ---- Voxelization and radiance injection (VoxelizePass, InjectPass) ------------------------
#define LIT_VOXEL_EMISSION_RANGE 16.0  // radiance (W/(sr·m²)) stored as 1.0 in the emission volume; = VoxelVolume::kEmissionRange
#define LIT_INJECT_GROUP_SIZE 8        // inject.comp.glsl work group: 8×8×8 voxels
// Occupied-voxel list (VoxelizePass appends, InjectPass runs over it with an indirect dispatch).
#define LIT_SSBO_OCCUPIED_VOXELS 2     // OccupiedVoxels: count, dispatch size, packed coordinates
#define LIT_SOLID_VOXELS_GROUP_SIZE 64  // solid_voxels.comp.glsl work group: 64 invocations of 32 columns each
#define LIT_INJECT_LIST_GROUP_SIZE 512 // inject.comp.glsl work group over the list: its 8³ group as 512 entries (65535 groups = 33.5 M voxels)
// Which voxels the occupied-voxel list holds: one bit per voxel of the N³ volume (index x + N(y +
// Nz)), set by the voxelization when it appends a voxel, so that a voxelization of changed boxes
// only (VoxelChangeTracker) appends the voxels new to the list and keeps its order. The outline
// pass's slot: never bound with it.
#define LIT_SSBO_LISTED_VOXELS 4
// Which empty voxels lie inside a solid (SolidVoxelsPass, solid_voxels.comp.glsl): one bit per
// voxel (index x + N(y + Nz)), so that the voxel rays never start in one. The exposure's slot: never
// bound with the voxel passes.
#define LIT_SSBO_SOLID_VOXELS 3
// Occupied parents (MipmapPass::listOccupiedParents): per mip level k ≥ 1 the voxels of level k
// with an occupied voxel below them, listed once each, so the mip chain is built over them only.
// Header: LIT_MIP_LIST_LEVELS × uvec4 (count, indirect dispatch x, y, z; index = level, 0 unused),
// then the lists and the levels' bitmasks (offsets from MipmapPass). Work groups of
// LIT_INJECT_LIST_GROUP_SIZE entries, as over the occupied-voxel list.
#define LIT_SSBO_MIP_PARENTS 5
// The voxel rays' first hits (RayHitCache, bounce.comp.glsl): one uint per occupied-
// list entry, side (front, back) and ray, recorded by a trace and replayed while the voxels stay.
#define LIT_SSBO_VOXEL_RAY_HITS 6
// The ray-hit cache's epochs (RayHitCache): per list entry, the epoch its hits were recorded in;
// a hit recorded before a changed box's epoch whose ray crosses that box is marched again
// (uniforms uChangedBoxMin/Max). The mip parents' slot: never bound with the traces.
#define LIT_SSBO_VOXEL_RAY_EPOCHS 5
// A near level's scroll (VoxelScrollPass, voxel_scroll.comp.glsl): per occupied-list entry the
// texels it lifts from its voxel's old place before placing them at the new one
// (LIT_SCROLL_SAVED_TEXELS uvec4 each). The ray hits' slot: never bound with the traces.
#define LIT_SSBO_VOXEL_SCROLL 6
#define LIT_SCROLL_SAVED_TEXELS 4
// Its images besides the material and radiance volumes' own units: the texels the pixels gather
// (with the materials), or the traced irradiance, the bounce and the texels being written (alone).
#define LIT_IMG_SCROLL_SHOWN_TEXELS 4
#define LIT_IMG_SCROLL_TRACED 0
#define LIT_IMG_SCROLL_BOUNCE 1
#define LIT_IMG_SCROLL_WRITTEN_TEXELS 2
// The most boxes a voxelization of changed boxes passes to the shaders (VoxelChangeTracker::kMaxBoxes):
// the ray-hit cache's changed boxes, the injection's boxes of new level-0 light.
#define LIT_CHANGED_BOXES 8
// How much a bounce changed the voxels' light (bounce.comp.glsl with uMeasureChange, VoxelGi when
// GiSettings::bounces is every bounce): LIT_BOUNCE_CHANGE_BINS uints summing the luminance of the
// bounce's bounced light (radiance − direct), then as many summing its change from the bounce
// before, both in units of 1/LIT_BOUNCE_CHANGE_SCALE W/(sr·m²) (rounded stochastically). Voxels
// spread over the bins so that no bin overflows.
#define LIT_SSBO_BOUNCE_CHANGE 7
#define LIT_BOUNCE_CHANGE_BINS 32
#define LIT_BOUNCE_CHANGE_SCALE 256.0
#define LIT_MIP_LIST_LEVELS 10  // levels 0..9: a 512³ volume's whole chain

// ---- Cone choice (cone.glsl), mirrored by tracedCones() in renderer/scene/OverlayShapes.cpp ------
// Written once here so the cone-direction debug view draws the cones the shader traces.
// Diffuse: one cone along the normal, five at 60° from it, 72° apart in azimuth, in tangent space
// (x, y along the surface, z along the normal; sin60° = 0.8660254, cos60° = 0.5), weights W_i/π.
// cone.glsl explains the layout and derives the weights.
#define LIT_DIFFUSE_CONE_COUNT 6
#define LIT_DIFFUSE_CONE_DIRECTIONS vec3(0.0, 0.0, 1.0), vec3(0.8660254, 0.0, 0.5), vec3(0.2676166, 0.8236391, 0.5), vec3(-0.7006293, 0.5090370, 0.5), vec3(-0.7006293, -0.5090370, 0.5), vec3(0.2676166, -0.8236391, 0.5)
#define LIT_DIFFUSE_CONE_WEIGHTS 0.25, 0.15, 0.15, 0.15, 0.15, 0.15
// Accurate mode (footprint-bounded cones): each diffuse region is cut into LIT_CONE_STRATA² cells, one
// per cone set, the sets laid out as a LIT_CONE_STRATA × LIT_CONE_STRATA pattern over the reduced
// trace's texels (cone_strata.glsl) and averaged by ConeStrataFilterPass (docs/GI.md).
#define LIT_CONE_STRATA 4
#define LIT_CONE_NORMAL_OFFSET_VOXELS 1.7320508  // cone apex: √3 voxels along the normal off the surface
#define LIT_RAY_START_VOXELS 0.5  // voxel rays of flat voxels: off their surface's plane (bounce.comp.glsl)
#define LIT_SPECULAR_LOBE_SHARE 0.75             // share of the GGX lobe specular samples are drawn from
#define LIT_SPECULAR_APERTURE_MIN 0.02           // rad, narrowest specular cone
#define LIT_SPECULAR_APERTURE_MAX 1.0471976      // rad (π/3), widest specular cone
#define LIT_SPECULAR_MAX_SAMPLES 8               // specular cones per pixel at most
#define LIT_CONE_APERTURE_MAX 3.0                // rad, widest cone traceCone marches (apertures are clamped)
#define LIT_CONE_REUSE_TOLERANCE 1e-3            // rad: specular cones this much narrower still reuse diffuse ones

// ---- FrameUniforms::counts.w flags ----------------------------------------------------------------
#define LIT_FRAME_SPECULAR_ANTIALIASING 1  // the direct light's lobes widened by the pixel's footprint

// ---- Sky and exposure (sky.glsl = scene/Sky.cpp; AutoExposurePass) ------------------------------
#define LIT_SKY_NONE 0       // black
#define LIT_SKY_UNIFORM 1    // FrameUniforms::skyZenith everywhere
#define LIT_SKY_GRADIENT 2   // ground below the horizon, horizon → zenith above it
#define LIT_SKY_HDR 3        // the LIT_TEX_SKY image
#define LIT_SKY_GROUND_BLEND 4.0  // below the horizon the ground colour is reached at −y = 1/4 (14.5°)
#define LIT_EXPOSURE_BINS 64            // histogram bins; bin 0 counts black pixels (not metered)
#define LIT_EXPOSURE_LOG2_MIN -16.0     // log2 luminance (W/(sr·m²)) of bin 1's lower edge
#define LIT_EXPOSURE_LOG2_MAX 16.0      // and of the last bin's upper edge (0.5 stop per bin)
#define LIT_EXPOSURE_LOW_PERCENT 0.10   // the darkest 10 % of metered pixels are ignored ...
#define LIT_EXPOSURE_HIGH_PERCENT 0.95  // ... and the brightest 5 % (lamps, sky, speculars)
#define LIT_EXPOSURE_GROUP_SIZE 16      // luminance_histogram.comp.glsl: 16×16 pixels per group

// ---- Limits -------------------------------------------------------------------------------
#define LIT_MAX_LIGHTS 64            // lights beyond this are ignored with a warning
#define LIT_MAX_SHADOW_2D 16         // layers of the directional/spot shadow-map array
#define LIT_MAX_SHADOW_CUBE 8        // cubes in the point-light shadow-map array
#define LIT_MAX_SHADOW_CASCADES 4    // camera cascades per directional light (ShadowSettings::cascades)
#define LIT_MAX_CASCADED_LIGHTS 2    // directional lights with cascades; the others use their scene-wide map only

// ---- Enumerations -------------------------------------------------------------------------
#define LIT_LIGHT_DIRECTIONAL 0
#define LIT_LIGHT_POINT 1
#define LIT_LIGHT_SPOT 2

// Which image the lighting/tonemap passes show (RenderSettings::View).
#define LIT_VIEW_FINAL 0
#define LIT_VIEW_DIRECT_DIFFUSE 1
#define LIT_VIEW_INDIRECT_DIFFUSE 2
#define LIT_VIEW_DIRECT_SPECULAR 3
#define LIT_VIEW_INDIRECT_SPECULAR 4
#define LIT_VIEW_ALBEDO 5
#define LIT_VIEW_NORMAL 6
#define LIT_VIEW_SHADOW_MAP 7
#define LIT_VIEW_VOXELS 8
#define LIT_VIEW_ROUGHNESS_METALNESS 9
#define LIT_VIEW_VOXEL_SLICE 10
#define LIT_VIEW_VOXEL_LEVELS 11

// What the voxel debug views show (DebugViewSettings::voxelChannel, VoxelDebugPass).
#define LIT_VOXEL_CHANNEL_RADIANCE 0
#define LIT_VOXEL_CHANNEL_ALBEDO 1
#define LIT_VOXEL_CHANNEL_NORMAL 2
#define LIT_VOXEL_CHANNEL_OPACITY 3
#define LIT_VOXEL_CHANNEL_EMISSION 4

// How the radiance volume stores radiance (VoxelUniforms::traceOptions.z).
#define LIT_RADIANCE_FLOAT16 0  // RGBA16F: radiance as is
#define LIT_RADIANCE_RGBA8 1    // RGBA8: radiance × radianceScale.x, clipped to [0,1] (4× less memory)

#define LIT_ALPHA_OPAQUE 0
#define LIT_ALPHA_MASK 1
#define LIT_ALPHA_BLEND 2

// The textures a material samples (GpuScene::materialTextureMask), as bits of LIT_MATERIAL_TEXTURES
// (material.glsl): the G-buffer pass compiles a program per combination in use.
#define LIT_MATERIAL_TEXTURE_BASE_COLOR 1
#define LIT_MATERIAL_TEXTURE_METALLIC_ROUGHNESS 2
#define LIT_MATERIAL_TEXTURE_NORMAL 4
#define LIT_MATERIAL_TEXTURE_EMISSIVE 8
#define LIT_MATERIAL_TEXTURE_OCCLUSION 16
#define LIT_MATERIAL_TEXTURE_LAYERS 32  // any of the layers' textures (LIT_LAYER_TEXTURE_*)
#define LIT_MATERIAL_TEXTURES_ALL 63

// Which of the layers' textures a material has (GpuMaterial::layerTextures.x).
#define LIT_LAYER_TEXTURE_CLEARCOAT 1
#define LIT_LAYER_TEXTURE_CLEARCOAT_ROUGHNESS 2
#define LIT_LAYER_TEXTURE_SPECULAR 4
#define LIT_LAYER_TEXTURE_SPECULAR_COLOR 8
#define LIT_LAYER_TEXTURE_SHEEN_COLOR 16
#define LIT_LAYER_TEXTURE_SHEEN_ROUGHNESS 32
#define LIT_LAYER_TEXTURE_CLEARCOAT_NORMAL 64
// Not a texture: the G-buffer stores the coat's own normal (its clearcoatNormalTexture, or the
// interpolated normal where only the base is normal-mapped); without, the coat shares the base's.
#define LIT_LAYER_COAT_NORMAL_STORED 128

// A material's texture references in the order of Material's per-reference arrays (scene/Scene.h),
// then the extensions' references;
// elements 2 × slot and 2 × slot + 1 of the LIT_LOC_UV_TRANSFORMS uniform are that reference's
// KHR_texture_transform.
#define LIT_MATERIAL_SLOT_BASE_COLOR 0
#define LIT_MATERIAL_SLOT_METALLIC_ROUGHNESS 1
#define LIT_MATERIAL_SLOT_NORMAL 2
#define LIT_MATERIAL_SLOT_EMISSIVE 3
#define LIT_MATERIAL_SLOT_OCCLUSION 4
#define LIT_MATERIAL_SLOT_TRANSMISSION 5  // Material::transmissionTexture (KHR_materials_transmission)
#define LIT_MATERIAL_SLOT_CLEARCOAT 6     // the layers' textures, in scene/Scene.h kExtensionTextureSlots' order
#define LIT_MATERIAL_SLOT_CLEARCOAT_ROUGHNESS 7
#define LIT_MATERIAL_SLOT_SPECULAR 8
#define LIT_MATERIAL_SLOT_SPECULAR_COLOR 9
#define LIT_MATERIAL_SLOT_SHEEN_COLOR 10
#define LIT_MATERIAL_SLOT_SHEEN_ROUGHNESS 11
#define LIT_MATERIAL_SLOT_CLEARCOAT_NORMAL 12
#define LIT_MATERIAL_SLOT_THICKNESS 13  // Material::thicknessTexture (KHR_materials_volume; not a layer)
#define LIT_MATERIAL_SLOTS 14

// ---- Structs ------------------------------------------------------------------------------
// Per-frame camera and output parameters. std140, binding LIT_UBO_FRAME.
struct FrameUniforms {
    mat4 view;
    mat4 projection;
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 cameraPosition;   // xyz world position (m), w unused
    vec4 viewport;         // width, height (pixels), 1/width, 1/height
    vec4 exposure;         // x linear exposure multiplier, y shadow PCF radius (texels), zw unused
    ivec4 counts;          // x light count, y view (LIT_VIEW_*), z shadow debug layer, w flags (LIT_FRAME_*)
    vec4 skyZenith;        // rgb sky radiance straight up (W/(sr·m²)), w mode (LIT_SKY_*)
    vec4 skyHorizon;       // rgb at the horizon, w intensity multiplier (all modes)
    vec4 skyGround;        // rgb below the horizon, w unused
};

// One punctual light (KHR_lights_punctual). std430, binding LIT_SSBO_LIGHTS.
struct GpuLight {
    vec4 positionRange;    // xyz world position (m), w range (m; 0 = infinite)
    vec4 directionType;    // xyz unit direction the light travels (world), w LIT_LIGHT_*
    vec4 colorIntensity;   // rgb linear colour, a intensity (cd for point/spot, lux for directional)
    vec4 spotShadow;  // x spot angle scale, y spot angle offset (KHR spec), z shadow index (-1 none), w cascaded light
                      // slot (-1 none)
    vec4 shadowParams;     // x near (m), y far (m), z depth bias (constant), w slope-scaled bias
    mat4 shadowViewProjection;  // world → light clip space (directional, spot)
};

// One material. std430, binding LIT_SSBO_MATERIALS.
struct GpuMaterial {
    vec4 baseColorFactor;     // linear RGBA
    vec4 emissive;            // rgb emissive factor × strength, a unused
    vec4 params;              // x metallic, y roughness, z normal scale, w occlusion strength
    ivec4 textures;           // x base colour, y metallic-roughness, z normal, w emissive (1 = present)
    ivec4 modes;              // x occlusion texture present, y alpha mode (LIT_ALPHA_*), z double sided,
                              // w transmission texture present
    vec4 alpha;               // x alpha cutoff, y transmission (KHR_materials_transmission), z the volume's
                              // index of refraction (0: none, a thin sheet; scene/Sheets.h
                              // refractiveIndexOfVolume), w unused
    vec4 specular;            // rgb ((η − 1)/(η + 1))² · k · s before the clamp to s, a dielectric F90 = s
                              // (KHR_materials_ior, _specular; material_table.glsl materialDielectricF0)
    vec4 clearcoat;           // x coat weight, y coat roughness (perceptual), z the coat normal texture's scale
                              // (KHR_materials_clearcoat), w unused
    vec4 sheen;               // rgb sheen colour, a sheen roughness (perceptual) (KHR_materials_sheen)
    ivec4 layerTextures;      // x LIT_LAYER_TEXTURE_* bits: the layers' textures the material has; y 1: the
                              // volume's thickness texture present; zw unused
    vec4 volume;              // rgb absorption coefficient σ_a = −ln(attenuation colour) / attenuation distance
                              // (1/m, world), a thickness (m, the mesh's space); 0, 0: no volume
                              // (KHR_materials_volume; material.glsl materialVolumeTransmittance)
};

// The light view a shadow pass renders. std140, binding LIT_UBO_SHADOW_PASS.
struct ShadowPassUniforms {
    mat4 viewProjection;   // world → light clip space for this layer / cube face
    vec4 lightPosition;    // xyz world position (point lights), w far plane (m)
};

// One camera cascade of a directional light's shadow: an orthographic map fitted to a slice of the
// view frustum (renderer/passes/ShadowCascades.h).
struct GpuShadowCascade {
    mat4 viewProjection;  // world → light clip space
    vec4 params;  // x world size of a texel (m), y constant depth bias (this map's depth units), z layer, w unused
};

// The camera's cascades. std140, binding LIT_UBO_SHADOW_CASCADES.
struct ShadowCascadeUniforms {
    GpuShadowCascade cascades[LIT_MAX_CASCADED_LIGHTS * LIT_MAX_SHADOW_CASCADES];  // slot k's cascade c at k × MAX + c
    ivec4 counts;  // x cascades per cascaded light (0 = none drawn yet), yzw unused
};

// The voxel volume and cone-tracing parameters. std140, binding LIT_UBO_VOXEL.
// The volume is a cube: world point p maps to texture coordinate (p − volumeMin.xyz) / volumeMin.w.
struct VoxelUniforms {
    vec4 volumeMin;      // xyz world-space minimum corner (m), w side length of the cube (m)
    vec4 voxelInfo;      // x resolution N (voxels per side), y 1/N, z voxel size (m), w mip level count
    vec4 traceParams;    // x indirect intensity, y max trace distance (m), z step (× cone diameter), w diffuse cone aperture (rad)
    ivec4 traceOptions;  // x specular samples per pixel, y frame index (sample rotation), z radiance encoding (LIT_RADIANCE_*), w unused
    vec4 radianceScale;  // x multiplier applied when storing radiance, y multiplier when reading it back (= 1/x)
    vec4 giParams;       // x footprint bound (largest sampled voxel ÷ height above the surface; 0 = none),
                         // y anisotropic (1: directional volumes for levels ≥ 1, 0: isotropic mips), zw unused
};

#ifdef __cplusplus
static_assert(sizeof(VoxelUniforms) == 6 * 16);
static_assert(sizeof(FrameUniforms) == 4 * 64 + 7 * 16);
static_assert(sizeof(GpuLight) == 5 * 16 + 64);
static_assert(sizeof(GpuMaterial) == 11 * 16);
static_assert(sizeof(ShadowPassUniforms) == 64 + 16);
static_assert(sizeof(GpuShadowCascade) == 64 + 16);
static_assert(sizeof(ShadowCascadeUniforms) == LIT_MAX_CASCADED_LIGHTS * LIT_MAX_SHADOW_CASCADES * (64 + 16) + 16);
inline const vec3 kDiffuseConeDirections[LIT_DIFFUSE_CONE_COUNT] = {LIT_DIFFUSE_CONE_DIRECTIONS};
inline const float kDiffuseConeWeights[LIT_DIFFUSE_CONE_COUNT] = {LIT_DIFFUSE_CONE_WEIGHTS};
}  // namespace lit::gpu
#endif

#endif  // LIT_SHARED_H
