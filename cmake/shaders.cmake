# phongvk_compile_shaders(TARGET target OUTPUT_DIR dir SOURCES file... [EXACT_SKIP name...]
#                         [KEYS32_SKIP name...] [OPT_SKIP name...])
#
# Compiles GLSL to SPIR-V at build time with glslang and embeds it as C arrays: x.comp becomes
# spirv_x in x.spv.h; a graphics stage x.vert / x.frag becomes spirv_x_vert / spirv_x_frag in
# x_vert.spv.h / x_frag.spv.h (the stages of one pipeline share a base name). glslang writes a
# dependency file per shader, so editing an included header rebuilds exactly the shaders that
# include it. Every compute shader not named in EXACT_SKIP is also built as spirv_x_exact with
# EXACT_FLOAT_OPS=1: division and sqrt corrected to the correctly rounded result
# (shaders/exact_float.h), for devices whose own are off (vulkan/float_probe.h). A build of its own,
# not a specialization constant: lavapipe inlines both sides of every call before it drops the dead
# one, which lengthened every process's pipeline compiling (docs/DECISIONS.md). Every compute
# shader not named in KEYS32_SKIP is also built for the 32-bit key path, as spirv_x_k32 and
# spirv_x_k32_exact with PHONGVK_KEYS32=1: no 64-bit integer and no 8-bit storage anywhere in the
# module (docs/DESIGN.md "Visibility"); and as spirv_x_k32s and spirv_x_k32s_exact with
# PHONGVK_STORAGE_ARRAYS=1 too, for devices with small texel buffers (vulkan/context.h storageArrays).
# Every compute shader's floating-point operations are then decorated NoContraction
# (shaders/no_contraction.cpp: glslang's `precise` stops at function boundaries, and no optimizer
# may rewrite an operation the reference computes as written), and the module goes through
# spirv-opt -O unless its name is in OPT_SKIP, and is decorated again after it: the copies its loop
# unroller makes of a loop's body can lack the decoration (setupClipped's snapping did). The
# optimized module is what every driver compiles: lavapipe turns SPIR-V into NIR and optimizes it
# in every process, and inlining, scalar replacement and dead-code removal done once here take
# much of that off each process (docs/DECISIONS.md, "Shaders are optimized at build time").
# `target` is a custom target the users of the headers depend on.
find_program(PHONGVK_SPIRV_OPT spirv-opt REQUIRED)  # Debian: spirv-tools
set(PHONGVK_EMBED_SPIRV ${CMAKE_CURRENT_LIST_DIR}/embed_spirv.cmake)

function(phongvk_compile_shaders)
  cmake_parse_arguments(ARG "" "TARGET;OUTPUT_DIR" "SOURCES;EXACT_SKIP;KEYS32_SKIP;OPT_SKIP" ${ARGN})
  set(outputs)
  foreach(src ${ARG_SOURCES})
    get_filename_component(name ${src} NAME_WE)
    get_filename_component(stage ${src} LAST_EXT)
    get_filename_component(dir ${src} DIRECTORY)
    set(variants "${name}")
    if(stage STREQUAL ".comp")
      if(NOT name IN_LIST ARG_EXACT_SKIP)
        list(APPEND variants "${name}_exact")
      endif()
      if(NOT name IN_LIST ARG_KEYS32_SKIP)
        list(APPEND variants "${name}_k32" "${name}_k32_exact" "${name}_k32s" "${name}_k32s_exact")
      endif()
    else()
      string(SUBSTRING ${stage} 1 -1 stage)
      set(variants "${name}_${stage}")
    endif()
    foreach(variant ${variants})
      set(out ${ARG_OUTPUT_DIR}/${variant}.spv.h)
      set(defines)
      if(variant MATCHES "_exact$")
        list(APPEND defines -DEXACT_FLOAT_OPS=1)
      endif()
      if(variant MATCHES "_k32")
        list(APPEND defines -DPHONGVK_KEYS32=1)
      endif()
      if(variant MATCHES "_k32s")
        list(APPEND defines -DPHONGVK_STORAGE_ARRAYS=1)
      endif()
      add_custom_command(
        OUTPUT ${out}.spv
        COMMAND ${CMAKE_COMMAND} -E make_directory ${ARG_OUTPUT_DIR}
        COMMAND Vulkan::glslangValidator -V --target-env vulkan1.2 -I${dir} ${defines}
                --depfile ${out}.spv.d -o ${out}.spv ${src}
        MAIN_DEPENDENCY ${src}
        DEPFILE ${out}.spv.d
        COMMENT "glslang: ${variant} -> SPIR-V"
        VERBATIM)
      # The compute passes: every floating-point operation decorated NoContraction, then
      # spirv-opt's performance passes unless the pass is in OPT_SKIP. The graphics baseline's
      # stages are embedded as glslang wrote them: the device's own rules, as before.
      set(module ${out}.spv)
      set(steps)
      set(tools)
      if(stage STREQUAL ".comp")
        set(tools phongvk_no_contraction)
        list(APPEND steps COMMAND phongvk_no_contraction ${out}.spv ${out}.strict)
        set(module ${out}.strict)
        if(NOT name IN_LIST ARG_OPT_SKIP)
          list(APPEND steps COMMAND ${PHONGVK_SPIRV_OPT} -O --target-env=vulkan1.2 ${out}.strict -o ${out}.opt
                            COMMAND phongvk_no_contraction ${out}.opt ${out}.final)
          set(module ${out}.final)
        endif()
      endif()
      add_custom_command(
        OUTPUT ${out}
        ${steps}
        COMMAND ${CMAKE_COMMAND} -DINPUT=${module} -DOUTPUT=${out} -DNAME=spirv_${variant} -P ${PHONGVK_EMBED_SPIRV}
        DEPENDS ${out}.spv ${tools} ${PHONGVK_EMBED_SPIRV}
        COMMENT "SPIR-V to C array: ${variant}"
        VERBATIM)
      list(APPEND outputs ${out})
    endforeach()
  endforeach()
  add_custom_target(${ARG_TARGET} DEPENDS ${outputs})
endfunction()
