#include "gi/VoxelizePass.h"

#include <shared.h>

#include "gi/VoxelVolume.h"
#include "scene/GpuScene.h"
#include "scene/Scene.h"
#include "scene/SheenAlbedo.h"
#include "scene/SpecularMeanAlbedo.h"

namespace lit {

static_assert(VoxelVolume::kEmissionRange == static_cast<float>(LIT_VOXEL_EMISSION_RANGE),
              "voxelize/inject shaders decode emission with LIT_VOXEL_EMISSION_RANGE");

VoxelizePass::VoxelizePass(const std::filesystem::path& shaderRoot)
    : programs_(shaderRoot, "voxelize",
                {{GL_VERTEX_SHADER, "voxelize.vert.glsl"},
                 {GL_GEOMETRY_SHADER, "voxelize.geom.glsl"},
                 {GL_FRAGMENT_SHADER, "voxelize.frag.glsl"}}),
      framebuffer_("voxelize (no attachments)") {
    programs_.get(LayerTexturesKey{true});  // a broken shader fails at start-up
}

bool VoxelizePass::begin(const GpuScene& gpuScene, const VoxelVolume& volume) {
    const int n = volume.resolution();
    if (n <= 0 || gpuScene.empty()) {
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        return false;
    }
    if (framebufferSize_ != n) {
        // Rasterization without attachments takes its size from these defaults (GL 4.3).
        glNamedFramebufferParameteri(framebuffer_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, n);
        glNamedFramebufferParameteri(framebuffer_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, n);
        framebufferSize_ = n;
    }

    framebuffer_.bind();
    glViewport(0, 0, n, n);
    glDisable(GL_DEPTH_TEST);  // every fragment counts, not only the nearest
    glDisable(GL_CULL_FACE);   // both windings: the projection axis flips some triangles
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);

    program_ = &programs_.get(LayerTexturesKey{gpuScene.hasLayerTextures()});
    program_->use();
    volume.uniforms().bindBase(GL_UNIFORM_BUFFER, LIT_UBO_VOXEL);
    gpuScene.materials().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_MATERIALS);
    volume.occupiedList().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_OCCUPIED_VOXELS);
    volume.listedVoxels().bindBase(GL_SHADER_STORAGE_BUFFER, LIT_SSBO_LISTED_VOXELS);
    glProgramUniform1ui(program_->id(), program_->location("uOccupiedCapacity"), volume.occupiedCapacity());
    const auto& meanAlbedo = specularMeanAlbedoTable();
    glProgramUniform2fv(program_->id(), program_->location("uSpecularMeanAlbedo"), kSpecularMeanAlbedoSize,
                        &meanAlbedo[0].x);
    static const std::array<float, kSpecularMeanAlbedoSize> sheenMean = [] {
        std::array<float, kSpecularMeanAlbedoSize> out{};
        for (int j = 0; j < kSpecularMeanAlbedoSize; ++j)
            out[static_cast<std::size_t>(j)] = sheenMeanAlbedo(static_cast<float>(j) / (kSpecularMeanAlbedoSize - 1));
        return out;
    }();
    glProgramUniform1fv(program_->id(), program_->location("uSheenMeanAlbedo"), kSpecularMeanAlbedoSize,
                        sheenMean.data());
    // Image atomics need an integer format; the volumes are 3D, so bind all slices (layered).
    glBindImageTexture(LIT_IMG_VOXEL_ALBEDO, volume.albedo().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_NORMAL, volume.normal().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_EMISSION, volume.emission().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(LIT_IMG_VOXEL_SURFACE, volume.surface().id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    return true;
}

void VoxelizePass::setRegion(const VoxelBox& box) const {
    glProgramUniform3i(program_->id(), program_->location("uRegionMin"), box.min.x, box.min.y, box.min.z);
    glProgramUniform3i(program_->id(), program_->location("uRegionMax"), box.max.x, box.max.y, box.max.z);
}

void VoxelizePass::end() const {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // Injection reads the volumes as images and the list as a buffer and dispatch command; debug
    // views and tests read the volumes as textures.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void VoxelizePass::execute(const Scene& scene, const GpuScene& gpuScene, VoxelVolume& volume, DrawCounters& counters) {
    volume.clearMaterials();
    volume.resetOccupiedList();
    volume.clearRadianceLevel0();  // injection over the list writes occupied voxels only
    volume.clearRadianceMips();    // and the mip chain is built over their parents only
    if (!begin(gpuScene, volume)) return;
    const int n = volume.resolution();
    setRegion({glm::ivec3(0), glm::ivec3(n)});
    gpuScene.draw(scene, *program_, GpuScene::Bind::Everything, counters);
    end();
}

void VoxelizePass::executeBoxes(const Scene& scene, const GpuScene& gpuScene, VoxelVolume& volume,
                                const std::vector<VoxelBox>& boxes, const std::vector<ItemPose>& items,
                                DrawCounters& counters) {
    for (const VoxelBox& box : boxes) {
        volume.clearMaterials(box);
        volume.clearRadianceLevel0(box);  // outside the boxes level 0 keeps its light
    }
    volume.clearRadianceMips();
    if (!begin(gpuScene, volume)) return;
    // Each item's voxels, padded as the tracker pads its boxes.
    std::vector<VoxelBox> itemBoxes;
    itemBoxes.reserve(items.size());
    for (const ItemPose& pose : items)
        itemBoxes.push_back(voxelBoxOf(pose.bounds, volume.placement(), VoxelChangeTracker::kPadding));
    for (const VoxelBox& box : boxes) {
        setRegion(box);
        gpuScene.draw(scene, *program_, GpuScene::Bind::Everything, counters, [&](const DrawItem& item) {
            return itemBoxes[static_cast<std::size_t>(&item - gpuScene.items().data())].overlaps(box);
        });
    }
    end();
}

std::vector<ItemPose> itemPoses(const Scene& scene, const GpuScene& gpuScene) {
    std::vector<ItemPose> poses;
    poses.reserve(gpuScene.items().size());
    for (const DrawItem& item : gpuScene.items()) {
        const bool placed = item.node >= 0 && static_cast<std::size_t>(item.node) < scene.nodes.size();
        ItemPose pose;
        pose.world = placed ? scene.nodes[static_cast<std::size_t>(item.node)].world : glm::mat4(1.0f);
        pose.bounds = item.localBounds.transformed(pose.world);
        poses.push_back(pose);
    }
    return poses;
}

std::vector<std::uint32_t> readMaterialVoxels(const gl::Texture& materialVolume) {
    const gl::TextureDesc& d = materialVolume.desc();
    std::vector<std::uint32_t> texels(static_cast<std::size_t>(d.width) * d.height * d.depth);
    if (texels.empty() || !materialVolume) return {};
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(materialVolume.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      static_cast<GLsizei>(texels.size() * sizeof(std::uint32_t)), texels.data());
    return texels;
}

glm::vec4 unpackVoxel(std::uint32_t packed) {
    return glm::vec4(static_cast<float>(packed & 0xffu), static_cast<float>((packed >> 8) & 0xffu),
                     static_cast<float>((packed >> 16) & 0xffu), static_cast<float>(packed >> 24)) /
           255.0f;
}

std::size_t countOccupiedVoxels(const VoxelVolume& volume) {
    std::size_t count = 0;
    for (std::uint32_t texel : readMaterialVoxels(volume.albedo()))
        if ((texel >> 24) != 0) ++count;
    return count;
}

std::vector<glm::ivec3> occupiedVoxels(const VoxelVolume& volume) {
    const std::vector<std::uint32_t> texels = readMaterialVoxels(volume.albedo());
    const int n = volume.resolution();
    std::vector<glm::ivec3> voxels;
    for (std::size_t i = 0; i < texels.size(); ++i) {
        if ((texels[i] >> 24) == 0) continue;
        const int index = static_cast<int>(i);
        voxels.emplace_back(index % n, (index / n) % n, index / (n * n));
    }
    return voxels;
}

}  // namespace lit
