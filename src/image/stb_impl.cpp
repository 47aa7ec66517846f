// The one place stb_image is compiled, with hidden visibility: illum uses its own copy (decoding
// textures), never another library's — assimp pulls in libdraco, which exports a copy of stb of
// its own, and a system libstb may be a different version. stb_truetype is compiled static in
// text.cpp, its one user: Dear ImGui (the viewer) links the system's stb_truetype and stb_rect_pack,
// whose structures a copy of illum's would not match.
// The C library first, outside the pragma: its declarations must keep default visibility.
#include <assert.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#pragma GCC visibility push(hidden)
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
#pragma GCC visibility pop
