# The layering rule as a test (ctest: layering): each layer's private
# headers (sparse/internal, sparse/src, mesh/internal, mesh/src, codec/src,
# capi/src) are included only from that layer's sources, its tests
# (tests/<layer>), the fuzzers (tests/fuzz) and the benchmarks (bench),
# never from an installed header (<layer>/include); and the arrows point one
# way: sparse/ includes no mesh or codec header, mesh/ no codec header.
#
#   cmake -DSOURCE_DIR=<repo> [-DEXTRA_FILE=<file> -DEXTRA_AS=<path in repo>] -P check_layering.cmake
#
# EXTRA_FILE is checked as if it sat at EXTRA_AS (how the test that proves
# this check fails on a violation feeds it one). Exit status 1 and one line
# per offending include when the rule is broken.
cmake_minimum_required(VERSION 3.16)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_layering.cmake: -DSOURCE_DIR=<repository> is required")
endif()

# layer;private root;... : the private include roots of each layer.
set(layers sparse mesh codec capi)
set(sparse_roots sparse/internal sparse/src)
set(mesh_roots mesh/internal mesh/src)
set(codec_roots codec/src)
set(capi_roots capi/src)

# Every spelling under which a private header can be included: its path
# from its root (how the layer includes it), and its path from the
# repository (a relative path reaching into the layer's folder).
foreach(layer ${layers})
  set(${layer}_spellings "")
  foreach(root ${${layer}_roots})
    file(GLOB_RECURSE headers RELATIVE ${SOURCE_DIR}/${root} ${SOURCE_DIR}/${root}/*.h)
    foreach(h ${headers})
      list(APPEND ${layer}_spellings "${h}" "${root}/${h}")
    endforeach()
  endforeach()
endforeach()

# Who may include a layer's private headers.
function(may_reach_inside layer path out)
  set(ok FALSE)
  foreach(prefix ${layer}/ tests/${layer}/ tests/fuzz/ bench/)
    string(FIND "${path}" "${prefix}" at)
    if(at EQUAL 0)
      set(ok TRUE)
    endif()
  endforeach()
  set(${out} ${ok} PARENT_SCOPE)
endfunction()

set(violations "")
function(check_file file path)
  file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line ${includes})
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" name "${line}")
    # A path that climbs out (../) is judged by what it names in the tree.
    string(REGEX REPLACE "^(\\.\\./)+" "" name "${name}")
    foreach(layer ${layers})
      list(FIND ${layer}_spellings "${name}" hit)
      if(hit GREATER -1)
        # A header beside the includer (same folder) is that folder's own.
        get_filename_component(dir ${path} DIRECTORY)
        if(EXISTS ${SOURCE_DIR}/${dir}/${name})
          continue()
        endif()
        may_reach_inside(${layer} ${path} ok)
        if(path MATCHES "^[a-z]+/include/")
          set(ok FALSE)  # an installed header cannot reach what is not installed
        endif()
        if(NOT ok)
          list(APPEND violations "${path} includes \"${name}\", private to ${layer}/")
        endif()
      endif()
    endforeach()
    # The arrows: apps -> codec -> mesh -> sparse.
    if(path MATCHES "^sparse/" AND name MATCHES "^gab/(mesh|codec)/")
      list(APPEND violations "${path} includes \"${name}\": sparse/ sits below mesh/ and codec/")
    elseif(path MATCHES "^mesh/" AND name MATCHES "^gab/codec/")
      list(APPEND violations "${path} includes \"${name}\": mesh/ sits below codec/")
    endif()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

set(sources "")
foreach(folder apps bench capi codec mesh python sparse tests web)
  file(GLOB_RECURSE found RELATIVE ${SOURCE_DIR}
       ${SOURCE_DIR}/${folder}/*.h ${SOURCE_DIR}/${folder}/*.hpp ${SOURCE_DIR}/${folder}/*.c
       ${SOURCE_DIR}/${folder}/*.cc ${SOURCE_DIR}/${folder}/*.cpp)
  list(APPEND sources ${found})
endforeach()
foreach(path ${sources})
  check_file(${SOURCE_DIR}/${path} ${path})
endforeach()
if(EXTRA_FILE)
  check_file(${EXTRA_FILE} ${EXTRA_AS})
endif()

list(LENGTH sources count)
if(violations)
  foreach(v ${violations})
    message("layering: ${v}")
  endforeach()
  message(FATAL_ERROR "layering: a private header is reached from outside its layer (tests/layering/check_layering.cmake)")
endif()
message("layering: ${count} files, no private header reached from outside its layer")
