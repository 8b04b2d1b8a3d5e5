# The bench smoke test (CTest `bench_smoke`): phongvk_bench --quick into a fresh folder, then the
# report must hold its tables and the plot must exist. Run with -DBENCH=<binary> -DOUT_DIR=<folder>.
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
execute_process(COMMAND ${BENCH} --quick --out ${OUT_DIR}/BENCHMARKS.md --plot ${OUT_DIR}/bench_error.png
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "phongvk_bench --quick exited with ${status}")
endif()
file(READ ${OUT_DIR}/BENCHMARKS.md report)
foreach(expected "## Targets" "| scene | image | triangles | reference |" "### Memory" "## Mesh setup"
                 "## Run time against error" "**front**" "![run time against error](bench_error.png)"
                 "## End to end" "| fig7_orbit_white_red | 6 |" "| fig1_cube, new machine |"
                 "less pipelines / reference |" "### First renders" "| stress/huge_triangles.json |"
                 "above its second |" "## A new mesh each frame" "| gpu | 1250 | 640x480 |"
                 "## A moving object" "| gpu | 20000 | 1280x720 |" "## Point clouds" "| gpu | 199809 |")
  string(FIND "${report}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "BENCHMARKS.md lacks '${expected}':\n${report}")
  endif()
endforeach()
if(NOT EXISTS ${OUT_DIR}/bench_error.png)
  message(FATAL_ERROR "no plot written")
endif()
