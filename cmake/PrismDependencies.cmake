# Every dependency comes from a Debian package (scripts/install-deps.sh installs them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(glm REQUIRED)
find_package(fmt REQUIRED)
find_package(ZLIB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(benchmark REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
# OpenEXR 3 for prism::imaging (Debian: libopenexr-dev).
find_package(OpenEXR 3 REQUIRED CONFIG)
# tinygltf reads glTF 2.0 for prism::render's scene loader. Debian's libtinygltf-dev ships it as
# a shared library (built with stb_image and nlohmann json): target TinyGLTF::TinyGLTF.
find_package(TinyGLTF 2.7 REQUIRED CONFIG)
# libepoxy loads OpenGL and EGL for prism::gpu (no CMake config of its own).
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
# Embree 3 traces the CPU's rays (prism::rays: the path tracer, PRT's bake; Debian: libembree-dev).
find_package(embree 3 REQUIRED CONFIG)
find_package(Threads REQUIRED)
find_package(NLopt 2.7 REQUIRED CONFIG)  # Nelder–Mead for the atmosphere's wavelength optimiser
# GLFW opens the viewer's window and its GL context (prism_gpu_window only): target glfw.
find_package(glfw3 3.3 REQUIRED)
# Dear ImGui draws the viewer's interface (Debian: libimgui-dev; no CMake package, pkg-config).
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)

# libcsv (RFC 4180 tokenizer) ships neither a CMake config nor a pkg-config file.
find_path(CSV_INCLUDE_DIR csv.h REQUIRED)
find_library(CSV_LIBRARY csv REQUIRED)
add_library(prism_libcsv INTERFACE IMPORTED)
target_include_directories(prism_libcsv INTERFACE ${CSV_INCLUDE_DIR})
target_link_libraries(prism_libcsv INTERFACE ${CSV_LIBRARY})

if(PRISM_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
  find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
endif()
