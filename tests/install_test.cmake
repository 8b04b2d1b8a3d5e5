# The installed package, as another project meets it (CTest `install_consumer`): `cmake --install`
# into a fresh prefix; examples/render_scene (render_scene and dataset) built against it with find_package(phongvk CONFIG) and
# the same program built with pkg-config; both render scenes/basic.json on the reference backend
# to the same bytes as the tree's own `phongvk render --backend cpu`; the installed `phongvk`
# runs from its prefix and reports its version.
# With -DPYTHON=<interpreter> -DPYTHON_SITE=<site-packages under the prefix>, the Python package
# installed there renders the same bytes too.
# Run with -DBUILD_DIR=<build tree> -DSOURCE_DIR=<repository> -DOUT_DIR=<scratch folder> -DCXX=<compiler>.
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
set(prefix ${OUT_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "${command} exited with ${status}:\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/phongvk/phongvk.h bin/phongvk)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install did not install ${installed}")
  endif()
endforeach()
file(GLOB_RECURSE config ${prefix}/*/phongvkConfig.cmake)
file(GLOB_RECURSE version_file ${prefix}/*/phongvkConfigVersion.cmake)
file(GLOB_RECURSE pc ${prefix}/*/phongvk.pc)
if(NOT config OR NOT version_file OR NOT pc)
  message(FATAL_ERROR "no phongvkConfig.cmake, phongvkConfigVersion.cmake or phongvk.pc under ${prefix}")
endif()

# find_package(phongvk CONFIG REQUIRED) and the phongvk::phongvk target.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/render_scene -B ${OUT_DIR}/example -G Ninja
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX})
run(${CMAKE_COMMAND} --build ${OUT_DIR}/example)
run(${OUT_DIR}/example/render_scene ${SOURCE_DIR}/scenes/basic.json ${OUT_DIR}/find_package.png cpu)
# The dataset example: a model's views built in code, each view's files and cameras.json.
file(MAKE_DIRECTORY ${OUT_DIR}/views)
run(${OUT_DIR}/example/dataset ${SOURCE_DIR}/scenes/meshes/torus.obj ${OUT_DIR}/views 3 cpu)
file(READ ${OUT_DIR}/views/cameras.json cameras)
string(JSON views LENGTH "${cameras}" views)
string(JSON fx GET "${cameras}" intrinsics fx)
if(NOT views EQUAL 3 OR NOT fx EQUAL 500)
  message(FATAL_ERROR "dataset: cameras.json has ${views} views and fx ${fx}: ${cameras}")
endif()
foreach(file 000_rgb.png 001_depth.npy 002_mask.png)
  if(NOT EXISTS ${OUT_DIR}/views/${file})
    message(FATAL_ERROR "dataset: no ${file}")
  endif()
endforeach()

# pkg-config: the same program, compiled by hand.
get_filename_component(pc_dir ${pc} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run(pkg-config --cflags --libs phongvk)
string(STRIP "${run_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
run(${CXX} ${SOURCE_DIR}/examples/render_scene/main.cpp ${flags} -o ${OUT_DIR}/render_scene_pc)
get_filename_component(lib_dir ${config} DIRECTORY)
get_filename_component(lib_dir ${lib_dir} DIRECTORY)
get_filename_component(lib_dir ${lib_dir} DIRECTORY)
set(ENV{LD_LIBRARY_PATH} ${lib_dir})
run(${OUT_DIR}/render_scene_pc ${SOURCE_DIR}/scenes/basic.json ${OUT_DIR}/pkg_config.png cpu)
unset(ENV{LD_LIBRARY_PATH})

# The installed command finds its library from its own prefix.
run(${prefix}/bin/phongvk --version)
if(NOT run_output MATCHES "^phongvk [0-9]+\\.[0-9]+\\.[0-9]+ \\(")
  message(FATAL_ERROR "phongvk --version printed '${run_output}'")
endif()
run(${prefix}/bin/phongvk render ${SOURCE_DIR}/scenes/basic.json -o ${OUT_DIR}/cli.png --backend cpu)

# The Python package, from the prefix's site-packages (when the build has it): the same image.
if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_SITE})
  run(${PYTHON} -c "import phongvk, sys; phongvk.write_png(sys.argv[1], phongvk.Renderer('cpu').render(phongvk.load_scene(sys.argv[2])))"
      ${OUT_DIR}/python.png ${SOURCE_DIR}/scenes/basic.json)
  unset(ENV{PYTHONPATH})
  set(images find_package pkg_config python)
else()
  set(images find_package pkg_config)
endif()

foreach(image ${images})
  file(SHA256 ${OUT_DIR}/${image}.png got)
  file(SHA256 ${OUT_DIR}/cli.png want)
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "${image}.png differs from phongvk render's image")
  endif()
endforeach()
