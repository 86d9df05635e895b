# How fast the tree builds, not what it builds (issue 45): unity batches, precompiled headers
# and ccache. Each can be switched off on its own; the code compiles the same without them (CI's
# first pass builds with both switched off, so that a missing #include cannot hide behind a
# header that a precompiled one or a neighbour in the batch brought along; the platform layer,
# whose portable half only the other pass builds, is compiled file by file in every build).
#
#   -DLIGHTBENCH_UNITY=OFF   every source file a translation unit of its own
#   -DLIGHTBENCH_UNITY_BATCH_SIZE=N  sources per unity file (default 8)
#   -DLIGHTBENCH_PCH=OFF     no precompiled headers
#   -DLIGHTBENCH_CCACHE=OFF  no ccache, even where it is installed
#   -DLIGHTBENCH_LLD=OFF     the compiler's default linker, even where lld is installed
#
# Where the time went (bench/README.md, "Build and CI"): Qt's headers parsed again for every
# translation unit, and the tests' own code optimised like the product's. So a library is
# compiled in unity batches (a precompiled header made it no faster on top of them; without
# batches it gets one, from the Qt, GLM and standard headers its files share), and the tests,
# one source file each, share a precompiled header per set of Qt modules they link and are
# compiled at -O1 (see lb_add_test).

option(LIGHTBENCH_PCH "Precompile each library's Qt, GLM and standard headers" ON)
option(LIGHTBENCH_UNITY "Compile each library's sources in batches (CMake's unity build)" ON)
set(LIGHTBENCH_UNITY_BATCH_SIZE 8 CACHE STRING "Source files in one unity batch")
option(LIGHTBENCH_CCACHE "Compile through ccache where it is installed" ON)
option(LIGHTBENCH_LLD "Link with lld where it is installed" ON)

# Every target made after this line takes these as its defaults.
set(CMAKE_UNITY_BUILD ${LIGHTBENCH_UNITY})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${LIGHTBENCH_UNITY_BATCH_SIZE})

if(LIGHTBENCH_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(LB_CCACHE ccache)
  if(LB_CCACHE)
    # Debian's ccache 4.7 takes its settings from the environment, not from its command line:
    #  - a compile that uses a precompiled header is cached only when ccache is told that the
    #    header's macros and times may differ from the text's (its manual, "Precompiled
    #    headers");
    #  - depend mode: a miss does not run the preprocessor first (the compiler's own -MD list
    #    of headers is kept instead), which made a first build 17% slower than without ccache;
    #  - paths below the checkout are hashed as relative ones, so that a clone elsewhere (CI's
    #    next run, a second worktree) finds what this one cached.
    # env(1) where there is one: `cmake -E env` took 23 ms a compile to start, env 4.
    find_program(LB_ENV env)
    if(NOT LB_ENV)
      set(LB_ENV ${CMAKE_COMMAND} -E env)
    endif()
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${LB_ENV}
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        CCACHE_DEPEND=1 CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}
        ${LB_CCACHE})
    message(STATUS "lightbench: compiling through ${LB_CCACHE}")
  endif()
endif()
if(LIGHTBENCH_LLD)
  # Some 80 executables (the tests, the helpers) link the same static libraries: GNU ld took
  # 1.4-1.8 s for each under the sanitizers, lld 0.25-0.33 (bench/README.md, "Build and CI").
  include(CheckLinkerFlag)
  check_linker_flag(CXX -fuse-ld=lld LB_HAS_LLD)
  if(LB_HAS_LLD)
    add_link_options(-fuse-ld=lld)
    message(STATUS "lightbench: linking with lld")
  endif()
endif()
if(LIGHTBENCH_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  # clang writes the headers' times into its precompiled header, so that no cache could reuse it.
  add_compile_options("SHELL:-Xclang -fno-pch-timestamp")
endif()

# lb_included_system_headers(OUT MIN_FILES FILE...): the headers of Qt (<QString>), GLM
# (<glm/vec3.hpp>) and the standard library (<vector>) that at least MIN_FILES of FILE... include,
# standard ones first. Platform headers (<unistd.h>) are left to the files that need them.
function(lb_included_system_headers out min_files)
  set(names "")
  foreach(file IN LISTS ARGN)
    if(NOT EXISTS "${file}")
      continue()
    endif()
    file(STRINGS "${file}" lines REGEX "^#include <")
    set(seen "")
    foreach(line IN LISTS lines)
      if(line MATCHES "^#include <(Q[A-Za-z0-9]+|glm/[A-Za-z0-9_/]+\\.hpp|[a-z_]+)>")
        list(APPEND seen "${CMAKE_MATCH_1}")
      endif()
    endforeach()
    list(REMOVE_DUPLICATES seen)
    list(APPEND names ${seen})
  endforeach()
  set(std "")
  set(other "")
  set(done "")
  foreach(name IN LISTS names)
    if(name IN_LIST done)
      continue()
    endif()
    list(APPEND done "${name}")
    set(count 0)
    foreach(each IN LISTS names)
      if(each STREQUAL name)
        math(EXPR count "${count} + 1")
      endif()
    endforeach()
    if(count LESS min_files)
      continue()
    elseif(name MATCHES "^[a-z_]+$")
      list(APPEND std "<${name}>")
    else()
      list(APPEND other "<${name}>")
    endif()
  endforeach()
  list(SORT std)
  list(SORT other)
  set(${out} ${std} ${other} PARENT_SCOPE)
endfunction()

# lb_source_files(OUT TARGET): TARGET's C++ sources and headers in the source tree, absolute.
function(lb_source_files out target)
  get_target_property(sources ${target} SOURCES)
  get_target_property(dir ${target} SOURCE_DIR)
  set(files "")
  foreach(source IN LISTS sources)
    if(source MATCHES "^\\$<" OR NOT source MATCHES "\\.(cpp|h)$")
      continue()
    endif()
    get_filename_component(path "${source}" ABSOLUTE BASE_DIR "${dir}")
    if(EXISTS "${path}")
      list(APPEND files "${path}")
    endif()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# lb_translation_units(OUT TARGET): how many compiler runs TARGET's own sources take, file by file.
function(lb_translation_units out target)
  get_target_property(sources ${target} SOURCES)
  set(count 0)
  foreach(source IN LISTS sources)
    if(source MATCHES "\\.cpp$")
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
  set(${out} ${count} PARENT_SCOPE)
endfunction()

# lb_precompile_library_headers(TARGET...): a precompiled header for each TARGET that is compiled
# file by file in more than one run, from the headers its own files share. Not for one run (it
# would gain nothing) nor for unity batches (measured no faster: each batch parses its headers
# once, and making the header costs what it saves).
function(lb_precompile_library_headers)
  if(NOT LIGHTBENCH_PCH)
    return()
  endif()
  foreach(target IN LISTS ARGN)
    get_target_property(type ${target} TYPE)
    get_target_property(reused ${target} PRECOMPILE_HEADERS_REUSE_FROM)
    get_target_property(unity ${target} UNITY_BUILD)
    get_target_property(disabled ${target} DISABLE_PRECOMPILE_HEADERS)
    if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$" OR reused
       OR unity OR disabled)
      continue()
    endif()
    lb_translation_units(units ${target})
    if(units LESS 2)
      continue()
    endif()
    lb_source_files(files ${target})
    lb_included_system_headers(headers 2 ${files})
    if(headers)
      target_precompile_headers(${target} PRIVATE ${headers})
    endif()
  endforeach()
endfunction()

# lb_qt_modules(OUT TARGET): the Qt modules whose usage requirements TARGET compiles with (its
# links and theirs, but for link-only ones), sorted: QtTest's headers read their macros
# (QT_GUI_LIB, QT_WIDGETS_LIB), so only targets with the same set can share a precompiled header.
function(lb_qt_modules out target)
  set(pending ${target})
  set(visited "")
  set(modules "")
  while(pending)
    list(POP_FRONT pending item)
    if(item IN_LIST visited OR NOT TARGET ${item})
      continue()
    endif()
    list(APPEND visited ${item})
    if(item MATCHES "^Qt6::([A-Za-z]+)$")
      list(APPEND modules ${CMAKE_MATCH_1})
    endif()
    set(links "")
    if(item STREQUAL target)
      get_target_property(links ${item} LINK_LIBRARIES)
    endif()
    get_target_property(interface ${item} INTERFACE_LINK_LIBRARIES)
    foreach(link IN LISTS links interface)
      if(link AND NOT link MATCHES "^\\$<" AND NOT link MATCHES "-NOTFOUND$")
        list(APPEND pending ${link})
      endif()
    endforeach()
  endwhile()
  list(REMOVE_DUPLICATES modules)
  list(SORT modules)
  set(${out} ${modules} PARENT_SCOPE)
endfunction()

# lb_share_test_headers(COMMON_TARGET TARGET...): the tests TARGET..., one source file each, reuse
# one precompiled header per set of Qt modules, made by a target of their own that links the
# same modules and COMMON_TARGET (what every test links), from the headers that two or more of
# that set's test files (and the test headers beside them) include.
function(lb_share_test_headers common)
  if(NOT LIGHTBENCH_PCH)
    return()
  endif()
  set(keys "")
  foreach(target IN LISTS ARGN)
    lb_qt_modules(modules ${target})
    string(JOIN "_" key ${modules})
    list(APPEND keys ${key})
    list(APPEND members_${key} ${target})
  endforeach()
  list(REMOVE_DUPLICATES keys)
  foreach(key IN LISTS keys)
    set(files "")
    foreach(target IN LISTS members_${key})
      lb_source_files(own ${target})
      list(APPEND files ${own})
    endforeach()
    # The test headers they include ("window_fixture.h"), found beside the test files.
    set(local "")
    foreach(file IN LISTS files)
      file(STRINGS "${file}" lines REGEX "^#include \"")
      get_filename_component(dir "${file}" DIRECTORY)
      foreach(line IN LISTS lines)
        if(line MATCHES "^#include \"([^\"]+\\.h)\"")
          foreach(candidate "${dir}/${CMAKE_MATCH_1}" "${CMAKE_CURRENT_SOURCE_DIR}/common/${CMAKE_MATCH_1}")
            if(EXISTS "${candidate}")
              list(APPEND local "${candidate}")
            endif()
          endforeach()
        endif()
      endforeach()
    endforeach()
    list(REMOVE_DUPLICATES local)
    lb_included_system_headers(headers 2 ${files} ${local})
    list(LENGTH members_${key} users)
    if(NOT headers OR users LESS 2)
      continue()
    endif()
    # Named after the modules beyond what every test links: lb_test_headers_Gui_OpenGL.
    set(name ${key})
    foreach(common_module Core Platform Test)
      string(REGEX REPLACE "(^|_)${common_module}(_|$)" "\\1" name "${name}")
    endforeach()
    string(REGEX REPLACE "__+" "_" name "${name}")
    string(REGEX REPLACE "^_|_$" "" name "${name}")
    if(name STREQUAL "")
      set(name Core)
    endif()
    set(owner lb_test_headers_${name})
    set(source ${CMAKE_CURRENT_BINARY_DIR}/${owner}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "// The precompiled header's own compile (build_speed.cmake).\n")
    add_library(${owner} OBJECT ${source})
    set_target_properties(${owner} PROPERTIES AUTOMOC OFF)
    string(REPLACE "_" ";" links "${key}")
    list(TRANSFORM links PREPEND "Qt6::")
    target_link_libraries(${owner} PRIVATE ${links} ${common})
    target_precompile_headers(${owner} PRIVATE ${headers})
    foreach(target IN LISTS members_${key})
      target_precompile_headers(${target} REUSE_FROM ${owner})
      # AUTOMOC's file of a test is empty (the test includes its own .moc): loading the
      # precompiled header for it would cost more than the file.
      get_target_property(binary_dir ${target} BINARY_DIR)
      set_source_files_properties(${binary_dir}/${target}_autogen/mocs_compilation.cpp
                                  TARGET_DIRECTORY ${target} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endforeach()
  endforeach()
endfunction()

# lb_targets_below(OUT DIR): the targets defined in DIR and the folders below it.
function(lb_targets_below out dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    lb_targets_below(more ${subdir})
    list(APPEND targets ${more})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()
