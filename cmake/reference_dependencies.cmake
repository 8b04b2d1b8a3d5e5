# What reference/ needs from the system, for the main build (CMakeLists.txt) and the fuzz build
# (fuzz/CMakeLists.txt) alike, so the two cannot drift apart.
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(ZLIB REQUIRED)  # PNG deflate (reference/image.cpp)
set(PHONGVK_REFERENCE_LIBRARIES glm::glm nlohmann_json::nlohmann_json tinyobjloader::tinyobjloader ZLIB::ZLIB)
