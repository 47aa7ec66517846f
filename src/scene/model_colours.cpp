// What previews do to a model file's colours, and scene files on request (docs/models.md): colour
// textures decoded from sRGB, or the file's colours dropped for the material's.
#include <illum/import.h>

#include <map>

namespace illum {

void decodeColourTextures(std::vector<Object>& objects) {
  // One decoded copy per texture, however many objects share it.
  std::map<const Texture*, std::shared_ptr<const Texture>> decoded;
  const auto srgb = [&](std::shared_ptr<const Texture>& t) {
    if (!t || t->encoding() == TexelEncoding::Srgb) return;
    auto [it, inserted] = decoded.try_emplace(t.get(), nullptr);
    if (inserted) it->second = std::make_shared<const Texture>(t->baseImage(), TexelEncoding::Srgb, t->wraps());
    t = it->second;
  };
  for (Object& o : objects) {
    srgb(o.diffuseTexture);
    srgb(o.maps.emissive);
  }
}

void dropFileColours(std::vector<Object>& objects) {
  // One copy without colours per mesh, however many objects share it.
  std::map<const Mesh*, std::shared_ptr<const Mesh>> colourless;
  for (Object& obj : objects) {
    obj.diffuseTexture = nullptr;
    obj.maps = {};
    if (obj.mesh->colors.empty()) continue;
    auto& copy = colourless[obj.mesh.get()];
    if (!copy) {
      auto mesh = std::make_shared<Mesh>(*obj.mesh);
      mesh->colors.clear();
      copy = std::move(mesh);
    }
    obj.mesh = copy;
  }
}

}  // namespace illum
