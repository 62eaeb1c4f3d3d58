// The occupied parents of the mip levels (MipmapPass::listOccupiedParents, layout in shared.h):
// for each level k ≥ 1, every voxel of level k with an occupied level-0 voxel below it, listed
// once, packed as packVoxelCoord (voxel.glsl): x | y << 10 | z << 20. parentHeaders[4k] is level
// k's count, parentHeaders[4k + 1 .. 4k + 3] its DispatchIndirectCommand (groups of
// LIT_INJECT_LIST_GROUP_SIZE entries); the lists and the bitmasks that deduplicate them lie in
// parentData at offsets MipmapPass passes as uniforms.
#define LIT_MIP_PARENTS_BLOCK(qualifiers)                                         \
    layout(std430, binding = LIT_SSBO_MIP_PARENTS) qualifiers buffer MipParents { \
        uint parentHeaders[4 * LIT_MIP_LIST_LEVELS];                              \
        uint parentData[];                                                        \
    }

ivec3 unpackParentCoord(uint p) { return ivec3(int(p & 1023u), int((p >> 10) & 1023u), int(p >> 20)); }

// What a shader dispatched over one level's list (MipmapPass, glDispatchComputeIndirect) declares:
// uParentList (x the level, y the offset of its list in parentData) and listedParent(), this
// invocation's voxel of that level (false past the list's end).
#define LIT_MIP_PARENT_READER                                                                      \
    LIT_MIP_PARENTS_BLOCK(readonly);                                                               \
    uniform ivec2 uParentList;                                                                     \
    bool listedParent(out ivec3 p) {                                                               \
        uint index = gl_WorkGroupID.x * uint(LIT_INJECT_LIST_GROUP_SIZE) + gl_LocalInvocationIndex; \
        if (index >= parentHeaders[4 * uParentList.x]) return false;                              \
        p = unpackParentCoord(parentData[uint(uParentList.y) + index]);                            \
        return true;                                                                               \
    }
