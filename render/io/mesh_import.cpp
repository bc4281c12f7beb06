// The assimp import proper: one file into one object-space MeshData. It runs in the import
// child process (io/mesh_io.cpp), where a crash or a runaway allocation costs only that child.
#include "io/mesh_import.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "io/asset_content.h"
#include "io/asset_lights.h"
#include "io/asset_material.h"
#include "io/mesh_file_access.h"

namespace rs {

namespace {
bool isFinite(const aiVector3D& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 toDouble(const Vec3& v) {
    return glm::dvec3(v.x, v.y, v.z);
}

// In double, so small but valid triangles are not mistaken for zero-area ones.
bool zeroArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    glm::dvec3 n = glm::cross(toDouble(b) - toDouble(a), toDouble(c) - toDouble(a));
    return n == glm::dvec3(0.0);
}

// Drops vertices no kept triangle uses, so bounds() describes the surface only.
void compact(MeshData& mesh) {
    constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> remap(mesh.positions.size(), kUnused);
    std::vector<Vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    for (uint32_t& index : mesh.indices) {
        if (remap[index] == kUnused) {
            remap[index] = static_cast<uint32_t>(positions.size());
            positions.push_back(mesh.positions[index]);
            if (!mesh.normals.empty()) normals.push_back(mesh.normals[index]);
            if (!mesh.uvs.empty()) uvs.push_back(mesh.uvs[index]);
        }
        index = remap[index];
    }
    mesh.positions = std::move(positions);
    mesh.normals = std::move(normals);
    mesh.uvs = std::move(uvs);
}

// Files can carry unnormalised, zero or NaN normals; shading needs unit ones. Broken ones
// are replaced by the area-weighted average of the faces around the vertex.
void repairNormals(MeshData& mesh) {
    std::vector<Vec3> faceSums;
    for (Vec3& n : mesh.normals) {
        float length = glm::length(n);
        if (std::isfinite(length) && length > 0.0f) {
            n /= length;
            continue;
        }
        if (faceSums.empty()) {
            faceSums.assign(mesh.positions.size(), Vec3(0.0f));
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
                const uint32_t* i = &mesh.indices[t];
                Vec3 area = glm::cross(mesh.positions[i[1]] - mesh.positions[i[0]],
                                       mesh.positions[i[2]] - mesh.positions[i[0]]);
                for (int k = 0; k < 3; ++k) faceSums[i[k]] += area;
            }
        }
        Vec3 sum = faceSums[static_cast<std::size_t>(&n - mesh.normals.data())];
        float sumLength = glm::length(sum);
        // Faces that cancel exactly leave no direction to pick; any unit vector will do.
        n = sumLength > 0.0f && std::isfinite(sumLength) ? sum / sumLength : Vec3(0, 0, 1);
    }
}
/// The embedded images of `scene`, compressed ones (a file's bytes) only; an uncompressed
/// one (raw texels, rare) stays empty and a look that uses it is noted.
std::vector<AssetImage> embeddedImages(const aiScene& scene) {
    std::vector<AssetImage> images(scene.mNumTextures);
    for (unsigned i = 0; i < scene.mNumTextures; ++i) {
        const aiTexture* t = scene.mTextures[i];
        images[i].name = t->mFilename.C_Str();
        for (char c : std::string(t->achFormatHint, strnlen(t->achFormatHint, HINTMAXTEXTURELEN)))
            if (std::isalnum(static_cast<unsigned char>(c))) images[i].formatHint += c;
        if (t->mHeight == 0 && t->mWidth > 0 && t->mWidth <= kMaxAssetImageBytes)
            images[i].bytes.assign(reinterpret_cast<const char*>(t->pcData), t->mWidth);
    }
    return images;
}

/// A texture named by a path from the machine the asset was made on (an absolute path with a
/// drive letter, as FBX files often say) that is not there: the file of that name in the
/// asset's own folder, when there is one (as Blender finds missing files).
void findMovedTexture(ImageTexture& t, const std::string& assetDir,
                      std::vector<std::string>& notes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (t.image.resolvedPath.empty() || fs::exists(t.image.resolvedPath, ec)) return;
    const fs::path name = fs::path(t.image.file).filename();
    if (name.empty()) return;
    const fs::path here = fs::path(assetDir) / name;
    if (!fs::is_regular_file(here, ec)) return;
    notes.push_back("its texture \"" + t.image.file + "\" is not there; using \"" + name.string() +
                    "\" from the asset's folder");
    t.image.file = name.string();
    t.image.resolvedPath = here.string();
}

/// The looks of the materials that `mesh`'s parts use, their names made unique.
AssetContent collectAssetContent(const aiScene& scene, const std::string& file,
                                 const MeshData& mesh) {
    AssetContent content;
    content.images = embeddedImages(scene);
    AssetTextureContext context;
    context.assetDir = std::filesystem::path(file).parent_path().string();
    for (const AssetImage& image : content.images) context.embeddedNames.push_back(image.name);
    for (const MeshPart& part : mesh.parts) {
        if (!content.looks.empty() && content.looks.back().index == part.material) continue;
        if (part.material >= scene.mNumMaterials) continue;
        context.materialIndex = part.material;
        AssetMaterial mapped = mapAssetMaterial(*scene.mMaterials[part.material], context);
        AssetLook look;
        look.index = part.material;
        look.material = std::move(mapped.material);
        look.notes = std::move(mapped.notes);
        look.material.name = numberedName(look.material.name, [&](const std::string& name) {
            return std::any_of(content.looks.begin(), content.looks.end(),
                               [&](const AssetLook& l) { return l.material.name == name; });
        });
        if (auto* t = std::get_if<ImageTexture>(&look.material.pattern))
            findMovedTexture(*t, context.assetDir, look.notes);
        if (mapped.texture.source == AssetTexture::Source::Embedded) {
            const int image = mapped.texture.embeddedIndex;
            if (image >= 0 && std::size_t(image) < content.images.size() &&
                !content.images[std::size_t(image)].bytes.empty()) {
                look.embeddedImage = image;
                look.material.pattern = mapped.texture.look;
            } else {
                look.notes.push_back("its embedded texture " + mapped.texture.path +
                                     " is not a compressed image file; left untextured");
            }
        }
        content.looks.push_back(std::move(look));
    }
    return content;
}
/// The asset's lights and cameras, named uniquely (and never "") within the asset.
void addLightsAndViews(AssetContent& content, AssetLightsAndCameras found) {
    for (Light& light : found.lights) {
        light.name = numberedName(
            light.name.empty() ? "asset light" : light.name, [&](const std::string& name) {
                return std::any_of(content.lights.begin(), content.lights.end(),
                                   [&](const Light& l) { return l.name == name; });
            });
        content.lights.push_back(std::move(light));
    }
    for (AssetCamera& camera : found.cameras)
        content.views.push_back(
            {camera.name.empty() ? "asset camera" : camera.name, camera.camera});
    content.lightNotes = std::move(found.notes);
}
/// Every sub-mesh's vertices appended to `mesh`: positions, the first UV channel ((0, 0) for
/// vertices of sub-meshes without one; kept only when some sub-mesh has one), normals when
/// `smoothNormals`. bases[m] is sub-mesh m's first vertex. Empty, or why the asset is unfit.
std::string readVertices(const aiScene& scene, bool smoothNormals, MeshData& mesh,
                         std::vector<uint32_t>& bases) {
    bool anyUvs = false;
    bases.assign(scene.mNumMeshes, 0);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh* in = scene.mMeshes[m];
        bases[m] = static_cast<uint32_t>(mesh.positions.size());
        anyUvs = anyUvs || in->HasTextureCoords(0);
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            const aiVector3D& p = in->mVertices[v];
            if (!isFinite(p))
                return "vertex " + std::to_string(v) + " of mesh " + std::to_string(m) +
                       " is not a finite number (NaN or infinity)";
            mesh.positions.emplace_back(p.x, p.y, p.z);
            const aiVector3D uv =
                in->HasTextureCoords(0) ? in->mTextureCoords[0][v] : aiVector3D(0, 0, 0);
            if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
                return "texture coordinate " + std::to_string(v) + " of mesh " + std::to_string(m) +
                       " is not a finite number (NaN or infinity)";
            mesh.uvs.emplace_back(uv.x, uv.y);
            if (smoothNormals) {
                const aiVector3D n = in->HasNormals() ? in->mNormals[v] : aiVector3D(0, 0, 0);
                mesh.normals.emplace_back(n.x, n.y, n.z);
            }
        }
    }
    if (!anyUvs) mesh.uvs.clear();
    return {};
}

/// The sub-meshes' triangles appended to `mesh`, grouped by material so each material's are
/// one run (a MeshPart); points, lines and degenerate triangles left out (the latter
/// counted). Empty, or why the asset is unfit.
std::string readTriangles(const aiScene& scene, const std::vector<uint32_t>& bases,
                          MeshData& mesh) {
    std::vector<unsigned> byMaterial(scene.mNumMeshes);
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) byMaterial[m] = m;
    std::stable_sort(byMaterial.begin(), byMaterial.end(), [&](unsigned a, unsigned b) {
        return scene.mMeshes[a]->mMaterialIndex < scene.mMeshes[b]->mMaterialIndex;
    });
    for (unsigned m : byMaterial) {
        const aiMesh* in = scene.mMeshes[m];
        const uint32_t base = bases[m];
        const auto firstTriangle = static_cast<uint32_t>(mesh.indices.size() / 3);
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines are not surfaces
            const unsigned* i = face.mIndices;
            if (i[0] >= in->mNumVertices || i[1] >= in->mNumVertices || i[2] >= in->mNumVertices)
                return "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                       " refers to a vertex that does not exist";
            bool repeated = i[0] == i[1] || i[1] == i[2] || i[0] == i[2];
            if (repeated || zeroArea(mesh.positions[base + i[0]], mesh.positions[base + i[1]],
                                     mesh.positions[base + i[2]])) {
                ++mesh.droppedDegenerate;
                continue;
            }
            for (int k = 0; k < 3; ++k) mesh.indices.push_back(base + i[k]);
        }
        const auto count = static_cast<uint32_t>(mesh.indices.size() / 3) - firstTriangle;
        if (count == 0) continue;
        if (!mesh.parts.empty() && mesh.parts.back().material == in->mMaterialIndex)
            mesh.parts.back().triangleCount += count;
        else
            mesh.parts.push_back({firstTriangle, count, in->mMaterialIndex});
    }
    return {};
}
}  // namespace

MeshLoadResult importMeshWithAssimp(const std::string& file, bool smoothNormals) {
    MeshLoadResult result;
    auto fail = [&](const std::string& why) {
        result.error = why;
        return result;
    };
    // No Assimp::DefaultLogger is created: assimp then logs to its null logger, so loading
    // never writes to stdout.
    Assimp::Importer importer;
    importer.SetIOHandler(new MeshFileAccess);  // Owned by the importer (assimp's API).
    unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                     aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure;
    // Dropping flat normals first lets identical positions join into one vertex.
    flags |= smoothNormals ? aiProcess_GenSmoothNormals : aiProcess_DropNormals;
    // Lights and cameras are read before the geometry steps: pre-transforming the vertices
    // moves a glTF camera a second time and drops the nodes that place them (asset_lights.h).
    // The steps then run in assimp's own order, as if ReadFile had been given them.
    const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
    if (!scene) {
        std::string why = importer.GetErrorString();
        return fail(why.empty() ? "assimp could not read it" : "assimp: " + why);
    }
    AssetLightsAndCameras lightsAndCameras = assetLightsAndCameras(*scene, Mat4(1.0f));
    scene = importer.ApplyPostProcessing(flags & ~unsigned(aiProcess_ValidateDataStructure));
    if (!scene) {
        std::string why = importer.GetErrorString();
        return fail(why.empty() ? "assimp could not read it" : "assimp: " + why);
    }

    auto mesh = std::make_shared<MeshData>();
    mesh->sourcePath = file;
    std::vector<uint32_t> bases;
    if (std::string why = readVertices(*scene, smoothNormals, *mesh, bases); !why.empty())
        return fail(why);
    if (std::string why = readTriangles(*scene, bases, *mesh); !why.empty()) return fail(why);
    if (mesh->indices.empty()) {
        if (mesh->droppedDegenerate > 0)
            return fail("all " + std::to_string(mesh->droppedDegenerate) +
                        " triangles are degenerate (zero area)");
        return fail("contains no triangles");
    }
    compact(*mesh);
    if (smoothNormals) repairNormals(*mesh);
    AssetContent asset = collectAssetContent(*scene, file, *mesh);
    addLightsAndViews(asset, std::move(lightsAndCameras));
    result.asset = std::make_shared<const AssetContent>(std::move(asset));
    result.mesh = std::move(mesh);
    return result;
}

}  // namespace rs
