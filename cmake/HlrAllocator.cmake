# hlr_use_program_allocator(TARGET): links TARGET with tcmalloc_minimal, the hlr program's allocator
# (app/CMakeLists.txt says why), where it is found and the build is not HLR_SANITIZE (ASan's
# allocator must be the one there). Sets HLR_PROGRAM_ALLOCATOR to TRUE or FALSE in the caller.
function(hlr_use_program_allocator target)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND AND NOT TARGET PkgConfig::TCMALLOC)
    pkg_check_modules(TCMALLOC QUIET IMPORTED_TARGET GLOBAL libtcmalloc_minimal)
  endif()
  if(TARGET PkgConfig::TCMALLOC AND NOT HLR_SANITIZE)
    target_link_libraries(${target} PRIVATE PkgConfig::TCMALLOC)
    # Nothing calls tcmalloc by name, so Debian's default --as-needed would drop it silently: keep
    # every library named.
    target_link_options(${target} PRIVATE "LINKER:--no-as-needed")
    set(HLR_PROGRAM_ALLOCATOR TRUE PARENT_SCOPE)
  else()
    set(HLR_PROGRAM_ALLOCATOR FALSE PARENT_SCOPE)
  endif()
endfunction()
