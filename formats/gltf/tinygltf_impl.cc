// The one translation unit holding tinygltf's implementation (see tinygltf_private.h).
#define TINYGLTF_IMPLEMENTATION
#include "formats/gltf/tinygltf_private.h"
