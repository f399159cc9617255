# The algorithms' sources, split in two libraries: cg_algorithms, the pure library (GLM and the
# standard library only), and cg_io, the JSON layer over it (every *_json.cpp, io/ and study/).
# Included by the desktop's CMakeLists.txt and the browser's sandbox/web/CMakeLists.txt, so a
# new file or folder lands in the same library in both builds.
file(GLOB_RECURSE CG_ALL_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.cpp)
set(CG_IO_PATTERN "(_json\\.cpp$)|(/algorithms/io/)|(/algorithms/study/)")
set(CG_ALGORITHM_SOURCES ${CG_ALL_SOURCES})
list(FILTER CG_ALGORITHM_SOURCES EXCLUDE REGEX "${CG_IO_PATTERN}")
set(CG_IO_SOURCES ${CG_ALL_SOURCES})
list(FILTER CG_IO_SOURCES INCLUDE REGEX "${CG_IO_PATTERN}")
