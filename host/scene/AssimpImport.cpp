#include "AssimpImport.hpp"

#include <assimp/DefaultIOSystem.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>

#include "common/InputError.hpp"

namespace arp::host {

namespace {
// Assimp repairs some broken files quietly (it drops faces whose indices are
// out of range, with only a log warning); its warnings are collected so such
// a model is refused instead of shown with holes.
struct WarningLog : Assimp::LogStream {
  std::string text;
  void write(const char* message) override { text += message; }
};
struct ScopedLog {
  WarningLog* stream = new WarningLog;  // the logger owns it
  ScopedLog() {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(stream, Assimp::Logger::Warn | Assimp::Logger::Err);
  }
  ~ScopedLog() { Assimp::DefaultLogger::kill(); }
};
// The files a model names (an OBJ's mtllib, a glTF's buffers) are opened only
// when they are regular files: a FIFO or a device named there blocked the
// importer (until the import guard's 60 s) or read without end. The first
// refused is kept and named.
// (assimp's own Exists() opens the file to see whether it is there.)
struct RegularFilesOnly : Assimp::DefaultIOSystem {
  mutable std::string refused;
  bool regular(const char* file) const {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec) || std::filesystem::is_regular_file(file, ec)) return true;
    if (refused.empty()) refused = file;
    return false;
  }
  bool Exists(const char* file) const override { return regular(file) && Assimp::DefaultIOSystem::Exists(file); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    return regular(file) ? Assimp::DefaultIOSystem::Open(file, mode) : nullptr;
  }
};
}  // namespace

Mesh assimp_import(const std::string& path) {
  ScopedLog log;
  Assimp::Importer imp;
  auto* io = new RegularFilesOnly;  // the importer owns it
  imp.SetIOHandler(io);
  const aiScene* sc = imp.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                             aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                             aiProcess_ValidateDataStructure);
  if (!io->refused.empty())
    // (short: the import helper's message is quoted in 80 characters)
    throw InputError(path, "", "names " + quoted(std::filesystem::path(io->refused).filename().string()) + ": not a regular file");
  if (!sc || !sc->mRootNode || (sc->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    throw InputError(path, "", "cannot import the model: " + quoted(imp.GetErrorString()));  // assimp may quote the whole file
  if (log.stream->text.find("out-of-range indices") != std::string::npos)
    throw InputError(path, "", "corrupt model: some faces have out-of-range vertex indices");
  Mesh out;
  for (unsigned k = 0; k < sc->mNumMeshes; ++k) {
    const aiMesh* am = sc->mMeshes[k];
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;  // points and lines draw nothing
    const auto base = static_cast<uint32_t>(out.positions.size());
    for (unsigned i = 0; i < am->mNumVertices; ++i) {
      out.positions.push_back({am->mVertices[i].x, am->mVertices[i].y, am->mVertices[i].z});
      const aiVector3D* uv = am->mTextureCoords[0];
      out.uvs.push_back(uv ? glm::dvec2(uv[i].x, uv[i].y) : glm::dvec2(0.0));
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      for (int j = 0; j < 3; ++j) out.indices.push_back(base + face.mIndices[j]);
    }
  }
  if (out.indices.empty()) throw InputError(path, "", "the model has no triangles");
  return out;
}

}  // namespace arp::host
