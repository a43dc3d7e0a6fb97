// Fuzz builds only: tinygltf's implementation compiled from Debian's header with the fuzzer's coverage and
// sanitizer instrumentation. Linked into the glTF fuzzer as object code, it takes precedence over the
// uninstrumented libtinygltf.so, so libFuzzer sees (and ASan checks) the JSON and GLB parsing too.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
