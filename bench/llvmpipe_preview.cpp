#include "llvmpipe_preview.h"

#include "../tests/mesa_reference.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace illum::bench {
namespace {

const char* kVertex = R"(#version 120
varying vec3 vP;
varying vec3 vN;
varying vec2 vUV;
varying vec4 vColor;
void main() {
  vP = vec3(gl_ModelViewMatrix * gl_Vertex);
  vN = normalize(gl_NormalMatrix * gl_Normal);
  vUV = gl_MultiTexCoord0.xy;
  vColor = gl_Color;
  gl_Position = ftransform();
}
)";

// Per pixel: the material's model under GL's lights (gl_LightSource: eye space), as illum's
// shading/ composes it.
const char* kFragment = R"(#version 120
uniform int uLights;
uniform bool uLocalViewer;
uniform bool uTwoSided;
uniform int uModel;  // 0 blinn-phong, 1 phong, 2 lambert, 3 cook-torrance
uniform vec4 uAmbient, uDiffuse, uSpecular, uEmission;
uniform float uShininess;
uniform vec3 uBase, uF0;
uniform float uMetallic, uAlphaRough;
uniform bool uColored, uTextured, uBaseTexel, uSrgb;
uniform sampler2D uTexture;
varying vec3 vP;
varying vec3 vN;
varying vec2 vUV;
varying vec4 vColor;

const float PI = 3.14159265;
float powGL(float x, float e) { return e == 0.0 ? 1.0 : pow(max(x, 0.0), e); }

// Where light i is: L, attenuation times spot.
vec4 lightAt(int i, vec3 P) {
  vec3 L;
  float att = 1.0;
  if (gl_LightSource[i].position.w != 0.0) {
    vec3 d = gl_LightSource[i].position.xyz / gl_LightSource[i].position.w - P;
    float dist = length(d);
    L = d / dist;
    att = 1.0 / (gl_LightSource[i].constantAttenuation + gl_LightSource[i].linearAttenuation * dist +
                 gl_LightSource[i].quadraticAttenuation * dist * dist);
  } else {
    L = normalize(gl_LightSource[i].position.xyz);
  }
  if (gl_LightSource[i].spotCutoff != 180.0) {
    float s = dot(-L, normalize(gl_LightSource[i].spotDirection));
    att *= s >= gl_LightSource[i].spotCosCutoff ? powGL(s, gl_LightSource[i].spotExponent) : 0.0;
  }
  return vec4(L, att);
}

vec3 classic(vec3 P, vec3 N, vec3 V, vec3 ambient, vec3 diffuse) {
  vec3 c = uEmission.rgb + gl_LightModel.ambient.rgb * ambient;
  for (int i = 0; i < uLights; ++i) {
    vec4 l = lightAt(i, P);
    vec3 L = l.xyz;
    float NoL = dot(N, L);
    vec3 term = ambient * gl_LightSource[i].ambient.rgb + max(NoL, 0.0) * diffuse * gl_LightSource[i].diffuse.rgb;
    if (uModel != 2 && NoL > 0.0) {
      float lobe;
      if (uModel == 0) {
        vec3 H = L + V;
        float len = length(H);
        lobe = powGL(len > 0.0 ? dot(N, H) / len : 0.0, uShininess);
      } else {
        lobe = powGL(dot(2.0 * NoL * N - L, V), uShininess);
      }
      term += lobe * uSpecular.rgb * gl_LightSource[i].specular.rgb;
    }
    c += l.w * term;
  }
  return c;
}

vec3 cookTorrance(vec3 P, vec3 N, vec3 V, vec3 base) {
  vec3 c = uEmission.rgb + gl_LightModel.ambient.rgb * base;
  float a2 = uAlphaRough * uAlphaRough;
  float NoV = max(dot(N, V), 1e-4);
  vec3 f0 = mix(uF0, base, uMetallic);
  for (int i = 0; i < uLights; ++i) {
    vec4 l = lightAt(i, P);
    vec3 L = l.xyz;
    c += l.w * base * gl_LightSource[i].ambient.rgb;
    float NoL = dot(N, L);
    if (NoL <= 0.0 || l.w <= 0.0) continue;
    vec3 H = normalize(L + V);
    float NoH = max(dot(N, H), 0.0), VoH = max(dot(V, H), 0.0);
    float k = NoH * NoH * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * k * k);
    float vV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2), vL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    float Vis = 0.5 / (vV + vL);
    vec3 F = f0 + (1.0 - f0) * pow(1.0 - VoH, 5.0);
    c += l.w * NoL * ((1.0 - F) * (1.0 - uMetallic) * base * gl_LightSource[i].diffuse.rgb +
                      PI * D * Vis * F * gl_LightSource[i].specular.rgb);
  }
  return c;
}

vec3 srgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
  vec3 N = normalize(vN);
  if (uTwoSided && !gl_FrontFacing) N = -N;
  vec3 V = uLocalViewer ? normalize(-vP) : vec3(0.0, 0.0, 1.0);
  vec4 texel = uTextured ? texture2D(uTexture, vUV) : vec4(1.0);
  vec4 color;
  if (uModel == 3) {
    vec4 base = uColored ? vColor : vec4(uBase, uDiffuse.a);
    if (uBaseTexel) base *= texel;
    color = vec4(clamp(cookTorrance(vP, N, V, base.rgb), 0.0, 1.0), base.a);
  } else {
    vec4 ambient = uColored ? vColor : uAmbient, diffuse = uColored ? vColor : uDiffuse;
    color = vec4(clamp(classic(vP, N, V, ambient.rgb, diffuse.rgb), 0.0, 1.0), diffuse.a);
  }
  if (uTextured && !uBaseTexel) color *= texel;
  if (uSrgb) color.rgb = srgb(color.rgb);
  gl_FragColor = color;
}
)";

bool translucent(const Object& o) {
  return o.material.diffuse.a < 1 || (o.diffuseTexture && o.diffuseTexture->hasTransparency()) ||
         std::any_of(o.mesh->colors.begin(), o.mesh->colors.end(), [](const Color4& c) { return c.a < 1; });
}

}  // namespace

PreviewSession::PreviewSession(const Scene& scene, int samples)
    : scene_(scene), samples_(samples), pixels_(std::size_t(scene.width) * std::size_t(scene.height) * 4) {
  if (scene.lights.size() > 8) throw std::runtime_error("llvmpipe takes at most 8 lights");
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
  context_ = ctx;
  if (!OSMesaMakeCurrent(ctx, pixels_.data(), GL_UNSIGNED_BYTE, scene.width, scene.height)) {
    OSMesaDestroyContext(ctx);
    throw std::runtime_error("OSMesaMakeCurrent failed");
  }
  if (samples_ > 1) {
    GLint most = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &most);
    if (samples_ > most)
      throw std::runtime_error("llvmpipe takes at most " + std::to_string(most) + " samples, not " + std::to_string(samples_));
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glGenRenderbuffers(1, &colorBuffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, colorBuffer_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, scene.width, scene.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer_);
    glGenRenderbuffers(1, &depthBuffer_);
    glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, scene.width, scene.height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the multisampled framebuffer object is not complete");
  }

  glViewport(0, 0, scene.width, scene.height);
  const Color4 background = scene.background;
  const bool srgb = scene.display.encoding == Encoding::Srgb;
  const auto shown = [&](Real c) { return GLfloat(srgb ? srgbEncoded(c) : c); };
  glClearColor(shown(background.r), shown(background.g), shown(background.b), GLfloat(background.a));
  glClearDepth(1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glMatrixMode(GL_PROJECTION);
  test::loadMatrix(scene.camera.clipFromView(GLfloat(scene.width) / GLfloat(scene.height)));
  glMatrixMode(GL_MODELVIEW);
  test::loadMatrix(scene.camera.viewFromWorld());
  for (std::size_t i = 0; i < scene.lights.size(); ++i) test::setLight(unsigned(GL_LIGHT0 + i), scene.lights[i]);
  const GLfloat ambient[4] = {GLfloat(scene.lightModel.ambient.r), GLfloat(scene.lightModel.ambient.g),
                              GLfloat(scene.lightModel.ambient.b), 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);

  program_ = glCreateProgram();
  glAttachShader(program_, test::compileShader(GL_VERTEX_SHADER, kVertex));
  glAttachShader(program_, test::compileShader(GL_FRAGMENT_SHADER, kFragment));
  glLinkProgram(program_);
  GLint ok = 0;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("the preview program does not link");
  glUseProgram(program_);
  glUniform1i(glGetUniformLocation(program_, "uLights"), GLint(scene.lights.size()));
  glUniform1i(glGetUniformLocation(program_, "uLocalViewer"), scene.lightModel.localViewer);
  glUniform1i(glGetUniformLocation(program_, "uTwoSided"), scene.lightModel.twoSided);
  glUniform1i(glGetUniformLocation(program_, "uSrgb"), srgb);
  glUniform1i(glGetUniformLocation(program_, "uTexture"), 0);
  if (scene.blend) glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

  // Everything in buffer objects once: positions and normals, colours, uvs.
  std::vector<std::pair<Real, Draw>> back;  // translucent ones, by eye-space depth
  const Mat4 view = scene.camera.viewFromWorld();
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const Object& object = scene.objects[k];
    const Mesh& m = *object.mesh;
    if (m.indices.empty()) continue;
    Draw d;
    d.object = k;
    d.colors = !m.colors.empty();
    d.uvs = !m.uvs.empty() && object.diffuseTexture;
    std::vector<GLfloat> data;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      for (const Vec3& v : {m.positions[i], m.normals[i]}) data.insert(data.end(), {GLfloat(v.x), GLfloat(v.y), GLfloat(v.z)});
      if (d.colors) data.insert(data.end(), {GLfloat(m.colors[i].r), GLfloat(m.colors[i].g), GLfloat(m.colors[i].b), GLfloat(m.colors[i].a)});
      if (d.uvs) data.insert(data.end(), {GLfloat(m.uvs[i].x), GLfloat(m.uvs[i].y)});
    }
    glGenBuffers(1, &d.buffer);
    glBindBuffer(GL_ARRAY_BUFFER, d.buffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(GLfloat)), data.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &d.indices);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.indices);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.indices.size() * sizeof(std::uint32_t)), m.indices.data(), GL_STATIC_DRAW);
    if (d.uvs) {
      // GL's rows run bottom to top; sRGB colour textures decoded by the sampler, as illum does.
      const Image& image = object.diffuseTexture->baseImage();
      std::vector<std::uint8_t> rows(image.rgba.size());
      const std::size_t row = std::size_t(image.width) * 4;
      for (int y = 0; y < image.height; ++y) std::memcpy(&rows[std::size_t(y) * row], image.pixel(0, image.height - 1 - y), row);
      glGenTextures(1, &d.texture);
      glBindTexture(GL_TEXTURE_2D, d.texture);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      const auto wrap = [](TextureWrap w) -> GLint {  // the model's sampler, as illum reads it
        return w == TextureWrap::MirroredRepeat ? GL_MIRRORED_REPEAT : w == TextureWrap::ClampToEdge ? GL_CLAMP_TO_EDGE : GL_REPEAT;
      };
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap(object.diffuseTexture->wraps().s));
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap(object.diffuseTexture->wraps().t));
      const GLint format = object.diffuseTexture->encoding() == TexelEncoding::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
      glTexImage2D(GL_TEXTURE_2D, 0, format, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
      glGenerateMipmap(GL_TEXTURE_2D);
    }
    if (scene.blend && translucent(object)) {
      Vec3 lo(std::numeric_limits<Real>::max()), hi(-std::numeric_limits<Real>::max());
      for (const Vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
      back.push_back({(view * object.worldFromObject * Vec4((lo + hi) * Real(0.5), 1)).z, d});
    } else {
      draws_.push_back(d);
    }
  }
  std::stable_sort(back.begin(), back.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [depth, d] : back) draws_.push_back(d);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

PreviewSession::~PreviewSession() {
  for (const Draw& d : draws_) {
    const GLuint buffers[2] = {d.buffer, d.indices};
    glDeleteBuffers(2, buffers);
    if (d.texture) glDeleteTextures(1, &d.texture);
  }
  if (framebuffer_) {
    glDeleteFramebuffers(1, &framebuffer_);
    const GLuint buffers[2] = {colorBuffer_, depthBuffer_};
    glDeleteRenderbuffers(2, buffers);
  }
  if (program_) glDeleteProgram(program_);
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void PreviewSession::draw() {
  if (framebuffer_) glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Mat4 view = scene_.camera.viewFromWorld();
  const auto uniform = [&](const char* name) { return glGetUniformLocation(program_, name); };
  for (const Draw& d : draws_) {
    const Object& object = scene_.objects[d.object];
    const Material& m = object.material;
    test::loadMatrix(view * object.worldFromObject);
    const LightingModel model = modelOf(m, scene_.model);
    glUniform1i(uniform("uModel"), model == LightingModel::CookTorrance ? 3
                                   : model == LightingModel::Phong      ? 1
                                   : model == LightingModel::Lambert    ? 2
                                                                        : 0);
    glUniform4f(uniform("uAmbient"), GLfloat(m.ambient.r), GLfloat(m.ambient.g), GLfloat(m.ambient.b), GLfloat(m.ambient.a));
    glUniform4f(uniform("uDiffuse"), GLfloat(m.diffuse.r), GLfloat(m.diffuse.g), GLfloat(m.diffuse.b), GLfloat(m.diffuse.a));
    glUniform4f(uniform("uSpecular"), GLfloat(m.specular.r), GLfloat(m.specular.g), GLfloat(m.specular.b), 1);
    glUniform4f(uniform("uEmission"), GLfloat(m.emission.r), GLfloat(m.emission.g), GLfloat(m.emission.b), 1);
    glUniform1f(uniform("uShininess"), GLfloat(m.shininess));
    const PhysicalMaterial p = physicalOf(m);
    const Real roughness = std::clamp(p.roughness, Real(0.045), Real(1));
    glUniform3f(uniform("uBase"), GLfloat(p.baseColor.r), GLfloat(p.baseColor.g), GLfloat(p.baseColor.b));
    glUniform3f(uniform("uF0"), GLfloat(p.f0.r), GLfloat(p.f0.g), GLfloat(p.f0.b));
    glUniform1f(uniform("uMetallic"), GLfloat(p.metallic));
    glUniform1f(uniform("uAlphaRough"), GLfloat(roughness * roughness));
    glUniform1i(uniform("uColored"), d.colors);
    glUniform1i(uniform("uTextured"), d.texture != 0);
    glUniform1i(uniform("uBaseTexel"), d.texture != 0 && model == LightingModel::CookTorrance);
    if (scene_.blend && translucent(object)) glEnable(GL_BLEND);
    else glDisable(GL_BLEND);
    glBindBuffer(GL_ARRAY_BUFFER, d.buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.indices);
    const GLsizei stride = GLsizei((6 + (d.colors ? 4 : 0) + (d.uvs ? 2 : 0)) * sizeof(GLfloat));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, stride, nullptr);
    glNormalPointer(GL_FLOAT, stride, reinterpret_cast<const void*>(3 * sizeof(GLfloat)));
    if (d.colors) {
      glEnableClientState(GL_COLOR_ARRAY);
      glColorPointer(4, GL_FLOAT, stride, reinterpret_cast<const void*>(6 * sizeof(GLfloat)));
    }
    if (d.uvs) {
      glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      glTexCoordPointer(2, GL_FLOAT, stride, reinterpret_cast<const void*>((d.colors ? 10 : 6) * sizeof(GLfloat)));
      glBindTexture(GL_TEXTURE_2D, d.texture);
    }
    glDrawElements(GL_TRIANGLES, GLsizei(object.mesh->indices.size()), GL_UNSIGNED_INT, nullptr);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  }
  if (framebuffer_) {
    // The resolve into the window's buffer.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, scene_.width, scene_.height, 0, 0, scene_.width, scene_.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  glFinish();
}

Image PreviewSession::image() const {
  Image image(scene_.width, scene_.height);
  const std::size_t row = std::size_t(scene_.width) * 4;
  for (int y = 0; y < scene_.height; ++y) std::memcpy(image.pixel(0, y), &pixels_[std::size_t(scene_.height - 1 - y) * row], row);
  return image;
}

}  // namespace illum::bench
