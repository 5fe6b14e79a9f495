# `cmake --install build [--prefix DIR]`: the static libraries a game links, their headers under
# include/lumagraph (included as "api/renderer.h", "graph/compiler.h", ... like inside the tree)
# and a CMake package, so that find_package(lumagraph CONFIG REQUIRED) gives
#   lumagraph::graph    graph files, schemas, the compiler and its plan (no Vulkan)
#   lumagraph::runtime  the Vulkan layer, images, worlds and the executor
#   lumagraph::nodes    every built-in node's schema and kernel
#   lumagraph::api      the Renderer (api/renderer.h): load a graph, render a world
# Shaders and node schemas are embedded in the libraries, so no data files travel with them.
# The libraries these four are built from are exported too (lumagraph::gpu, ::scene, ...):
# a static library's dependencies have to be linked by whoever links it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

add_library(lumagraph_runtime INTERFACE)
target_link_libraries(lumagraph_runtime INTERFACE lumagraph_gpu lumagraph_image lumagraph_scene lumagraph_exec)
add_library(lumagraph_nodes INTERFACE)
target_link_libraries(lumagraph_nodes INTERFACE lumagraph_node_kernels lumagraph_node_schemas)
set_target_properties(lumagraph_renderer PROPERTIES EXPORT_NAME api)

# Every lumagraph_* target that `roots` link, directly or not, and the roots.
function(lg_library_closure out)
  set(pending ${ARGN})
  set(found)
  while(pending)
    list(POP_FRONT pending target)
    if(NOT TARGET ${target} OR target IN_LIST found)
      continue()
    endif()
    list(APPEND found ${target})
    get_target_property(type ${target} TYPE)
    get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(private_links ${target} LINK_LIBRARIES)
      list(APPEND links ${private_links})
    endif()
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
      if(link MATCHES "^lumagraph_")
        list(APPEND pending ${link})
      endif()
    endforeach()
  endwhile()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

lg_library_closure(exported lumagraph_graph lumagraph_runtime lumagraph_nodes lumagraph_renderer)
foreach(target IN LISTS exported)
  get_target_property(name ${target} EXPORT_NAME)
  if(NOT name)
    string(REGEX REPLACE "^lumagraph_" "" name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  endif()
endforeach()

set(include_dir ${CMAKE_INSTALL_INCLUDEDIR}/lumagraph)
set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/lumagraph)
install(TARGETS ${exported} EXPORT lumagraphTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${include_dir})
install(DIRECTORY graph runtime nodes api DESTINATION ${include_dir} FILES_MATCHING PATTERN "*.h" PATTERN shaders EXCLUDE)
install(EXPORT lumagraphTargets NAMESPACE lumagraph:: DESTINATION ${package_dir})
configure_package_config_file(cmake/lumagraphConfig.cmake.in ${PROJECT_BINARY_DIR}/lumagraphConfig.cmake
                              INSTALL_DESTINATION ${package_dir})
# 0.x: a new minor version may break the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lumagraphConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lumagraphConfig.cmake ${PROJECT_BINARY_DIR}/lumagraphConfigVersion.cmake
        DESTINATION ${package_dir})
