// The implementations of the single-header libraries, which the desktop build links from
// Debian's libstb and libtinyobjloader (native libraries, of no use to emscripten).
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
