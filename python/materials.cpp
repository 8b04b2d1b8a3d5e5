// materials.cpp — materials, textures, render settings and placing meshes (see bindings.h).
#include "bindings.h"

#include "tools/option_text.h"

namespace phongvk::python {

void setFields(py::object& value, const py::dict& fields, const std::string& what) {
  for (const auto& [key, field] : fields) {
    const std::string name = py::str(key);
    if (name.empty() || name[0] == '_' || !py::hasattr(value, name.c_str())) {
      std::string allowed;
      for (const py::handle attribute : py::module_::import("builtins").attr("dir")(value)) {
        const std::string a = py::str(attribute);
        if (a[0] != '_') allowed += (allowed.empty() ? "" : ", ") + a;
      }
      throw SceneError(what + ": unknown key '" + name + "' (allowed: " + allowed + ")");
    }
    value.attr(name.c_str()) = field;
  }
}

Texture texelsOfArray(const py::array& array, const char* name) {
  const int width = int(array.shape(1)), height = int(array.shape(0));
  const auto* base = static_cast<const uint8_t*>(array.data());
  const py::ssize_t rowStride = array.strides(0), pixelStride = array.strides(1);
  if (array.ndim() == 2) {  // 16-bit grey
    return Texture::fromRows(width, height, [&](int y, uint8_t* rgba) {
      for (int x = 0; x < width; ++x, rgba += 4) {
        uint16_t grey;
        std::memcpy(&grey, base + y * rowStride + x * pixelStride, sizeof grey);
        rgba[0] = rgba[1] = rgba[2] = uint8_t(grey >> 8);
        rgba[3] = 255;
      }
    }, name);
  }
  const py::ssize_t channelStride = array.strides(2);
  const bool alpha = array.shape(2) == 4;
  return Texture::fromRows(width, height, [&](int y, uint8_t* rgba) {
    for (int x = 0; x < width; ++x, rgba += 4) {
      const uint8_t* pixel = base + y * rowStride + x * pixelStride;
      for (int c = 0; c < 3; ++c) rgba[c] = pixel[c * channelStride];
      rgba[3] = alpha ? pixel[3 * channelStride] : 255;
    }
  }, name);
}

Texture textureOfArray(const py::array& array, const char* name) {
  checkPngArray(array, name);
  checkTextureSize(array.shape(1), array.shape(0), name);
  try {
    return texelsOfArray(array, name);
  } catch (const std::bad_alloc&) {
    raiseMemoryError(std::string(name) + ": no memory for its " + std::to_string(array.shape(1)) + " x " +
                     std::to_string(array.shape(0)) + " texels (" + std::to_string(array.shape(0) * array.shape(1) * 4) +
                     " bytes)");
  }
}

std::string textureRepr(const Texture& texture) {
  return "<phongvk.Texture " + std::to_string(texture.width()) + " x " + std::to_string(texture.height()) + ">";
}

void setTexture(Material& material, const py::object& texture) {
  material.texture.clear();
  material.textureImage.reset();
  if (texture.is_none()) return;
  if (py::isinstance<py::str>(texture) || py::hasattr(texture, "__fspath__")) {
    material.texture = py::str(py::module_::import("os").attr("fspath")(texture));
  } else if (py::isinstance<Texture>(texture)) {
    material.textureImage = texture.cast<Texture>();
  } else {
    material.textureImage = textureOfArray(numberArray(texture, "texture", PNG_ARRAYS), "texture");
  }
}

std::optional<Material> materialOf(const py::object& material) {
  if (material.is_none()) return std::nullopt;
  if (py::isinstance<Material>(material)) return material.cast<Material>();
  if (!py::isinstance<py::dict>(material)) {
    throw py::type_error("material: expected a phongvk.Material, a dict of its fields, a material name or None, got " +
                         std::string(py::str(py::type::of(material).attr("__name__"))));
  }
  py::object value = py::cast(Material{});
  setFields(value, material.cast<py::dict>(), "material");
  return value.cast<Material>();
}

TriangleMesh meshOf(const py::object& vertices, const py::object& faces, const py::object& normals,
                    const py::object& uvs, const py::object& colors) {
  if (!py::isinstance<TriangleMesh>(vertices)) return TriangleMesh(meshArrays(vertices, faces, normals, uvs, colors));
  if (!faces.is_none() || !normals.is_none() || !uvs.is_none() || !colors.is_none())
    throw py::type_error("faces, normals, uvs and colors: not given with a phongvk.Mesh, which has its own");
  return vertices.cast<TriangleMesh>();
}

std::optional<Material> visualMaterial(const py::object& object) {
  if (!py::hasattr(object, "visual") || !py::hasattr(object.attr("visual"), "material")) return std::nullopt;
  const py::object material = object.attr("visual").attr("material");
  for (const char* name : {"image", "baseColorTexture"}) {
    if (!py::hasattr(material, name) || material.attr(name).is_none()) continue;
    Material textured;
    textured.textureImage = textureOfArray(numberArray(material.attr(name), "visual.material.image", PNG_ARRAYS),
                                           "visual.material.image");
    return textured;
  }
  return std::nullopt;
}

unsigned long long addPlaced(Scene& scene, const TriangleMesh& mesh, const py::object& object, const Matrix4& pose,
                             const py::object& material, bool closed, std::optional<int32_t> objectId) {
  ObjectId id;
  if (py::isinstance<py::str>(material)) {
    id = scene.add(mesh, pose, material.cast<std::string>(), closed);
  } else {
    const std::optional<Material> given = materialOf(material);
    id = scene.add(mesh, pose, given ? given : visualMaterial(object), closed);
  }
  if (objectId) {
    try {
      scene.setObjectId(id, *objectId);
    } catch (...) {
      scene.remove(id);  // the scene as it was
      throw;
    }
  }
  return id.value;
}

void addMesh(Scene& scene, const py::object& vertices, const py::object& faces, const py::object& normals,
             const py::object& material, bool closed, const py::object& uvs, const py::object& colors,
             std::optional<int32_t> objectId) {
  addPlaced(scene, meshOf(vertices, faces, normals, uvs, colors), vertices, IDENTITY_POSE, material, closed, objectId);
}

unsigned long long addObject(Scene& scene, const py::object& object, const py::object& faces, const py::object& pose,
                             const py::object& material, bool closed, const py::object& normals, const py::object& uvs,
                             const py::object& colors, std::optional<int32_t> objectId) {
  const TriangleMesh mesh = meshOf(object, faces, normals, uvs, colors);
  return addPlaced(scene, mesh, object, matrix4(pose, "pose"), material, closed, objectId);
}

bool isLightHandle(unsigned long long handle) { return handle & (1ull << 31); }

TriangleMesh meshFromFile(const FsPath& path, const std::optional<std::string>& up) {
  const ModelUp axis = up ? parseModelUp(*up) : ModelUp::Usual;
  py::gil_scoped_release release;
  return TriangleMesh::fromFile(path.text, axis);
}

Scene withRender(const Scene& scene, const py::object& settings, const py::kwargs& options) {
  py::object value = py::cast(scene.renderSettings());
  if (py::isinstance<RenderSettings>(settings)) {
    value = py::cast(settings.cast<RenderSettings>());
  } else if (py::isinstance<py::dict>(settings)) {
    setFields(value, settings.cast<py::dict>(), "render");
  } else if (!settings.is_none()) {
    throw py::type_error("settings: expected a phongvk.RenderSettings, a dict of its fields or None, got " +
                         std::string(py::str(py::type::of(settings).attr("__name__"))));
  }
  setFields(value, options, "render");
  return scene.withRender(value.cast<RenderSettings>());
}

}  // namespace phongvk::python
