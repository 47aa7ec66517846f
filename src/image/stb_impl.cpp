// The one place stb's single-header libraries are compiled, with hidden visibility: illum uses
// its own copy of stb_image (decoding textures) and stb_truetype (labels), never another
// library's — assimp pulls in libdraco, which exports a copy of stb of its own, and a system
// libstb may be a different version. Nothing else defines the *_IMPLEMENTATION macros.
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
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>
#pragma GCC visibility pop
