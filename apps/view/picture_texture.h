// Presenting the CPU's picture in the window at little cost of its own (issue 32: at most 2 ms a
// frame at 1280×720): the renderer chosen for the machine, and the picture copied into a texture
// of the format that renderer draws without converting.
#pragma once

#include <illum/image.h>

#include <SDL.h>

namespace illum::view {

// SDL's accelerated renderer on a real GPU; on a GL that is itself drawn on the CPU (Mesa's
// llvmpipe or softpipe, a machine without a GPU) SDL's software renderer on the window's own
// surface, which takes a copy and an X shared-memory put where the GL would rasterize the picture
// as a texture on threads that contend with illum's. SDL_RENDER_DRIVER, when set, decides.
// Null when neither can be made (SDL_GetError says why).
SDL_Renderer* createPresentingRenderer(SDL_Window* window);

// The picture's texture: RGBA8 bytes converted once, off SDL's generic blitters, into the pixel
// format the renderer draws straight (the window's, for the software renderer), and drawn
// opaque (the picture's alpha is its own: the background's colour is under it already).
class PictureTexture {
 public:
  PictureTexture(SDL_Window* window, SDL_Renderer* renderer);
  ~PictureTexture();
  PictureTexture(const PictureTexture&) = delete;
  PictureTexture& operator=(const PictureTexture&) = delete;

  // Replaces the texture's pixels with `image`'s (a new texture when its size changed).
  void update(const Image& image);
  SDL_Texture* texture() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  SDL_Renderer* renderer_;
  Uint32 format_;
  SDL_Texture* texture_ = nullptr;
  int width_ = 0, height_ = 0;
};

}  // namespace illum::view
