# What the scene and image libraries need from the system, for the main build (CMakeLists.txt) and
# the fuzz build (fuzz/CMakeLists.txt) alike, so the two cannot drift apart.
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(TinyGLTF REQUIRED)  # glTF 2.0: its header only (meshio/gltf_import.cpp compiles it)
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)  # PNG deflate and CRC (image/png_write.cpp)
# Texture decoding (image/png_decode.cpp, image/jpeg_decode.cpp): the codecs' own errors for a
# corrupt or truncated image, row by row into the texture.
pkg_check_modules(LIBPNG REQUIRED IMPORTED_TARGET libpng)
pkg_check_modules(LIBJPEG REQUIRED IMPORTED_TARGET libjpeg)
# Draco (Debian's libdraco-dev) decodes glTF's KHR_draco_mesh_compression (meshio/gltf_draco.cpp).
find_package(draco CONFIG REQUIRED)
set(PHONGVK_SCENE_LIBRARIES glm::glm nlohmann_json::nlohmann_json tinyobjloader::tinyobjloader draco::draco)
set(PHONGVK_IMAGE_LIBRARIES PkgConfig::LIBDEFLATE PkgConfig::LIBPNG PkgConfig::LIBJPEG)
# stb (Debian's libstb-dev) installs its headers under /usr/include/stb.
set(PHONGVK_STB_INCLUDE_DIR /usr/include/stb)
