// tinygltf and stb_image compiled from the Debian headers with the fuzzer's instrumentation
// (the shared libraries the normal build links are not instrumented, so the fuzzer would be
// blind inside them). Only tools/fuzz.sh compiles this file. tiny_gltf.h includes stb_image.h
// itself; STB_IMAGE_IMPLEMENTATION makes that include the implementation.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define STB_IMAGE_IMPLEMENTATION
#include <tiny_gltf.h>
