#include "mesa_reference.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace illum::test {
namespace {

// The equation of OpenGL 2.1 §2.14.1, written against GL's built-in light and material state so
// that the same glLight/glMaterial calls feed both paths. pow(0, 0) is undefined in GLSL, so the
// exponents of 0 are special-cased to GL's 0^0 = 1.
const char* kLightingGlsl = R"(
uniform int uLights;
uniform int uModel;  // 0 blinn-phong, 1 phong, 2 lambert
uniform bool uLocalViewer;

float powGL(float x, float e) { return e == 0.0 ? 1.0 : pow(max(x, 0.0), e); }

vec4 lightGL(vec3 P, vec3 N) {
  vec3 V = uLocalViewer ? normalize(-P) : vec3(0.0, 0.0, 1.0);
  vec3 c = gl_FrontMaterial.emission.rgb + gl_LightModel.ambient.rgb * gl_FrontMaterial.ambient.rgb;
  for (int i = 0; i < uLights; ++i) {
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
    float spot = 1.0;
    if (gl_LightSource[i].spotCutoff != 180.0) {
      float s = dot(-L, normalize(gl_LightSource[i].spotDirection));
      spot = s >= gl_LightSource[i].spotCosCutoff ? powGL(s, gl_LightSource[i].spotExponent) : 0.0;
    }
    float NoL = dot(N, L);
    vec3 term = gl_FrontMaterial.ambient.rgb * gl_LightSource[i].ambient.rgb +
                max(NoL, 0.0) * gl_FrontMaterial.diffuse.rgb * gl_LightSource[i].diffuse.rgb;
    if (uModel != 2 && NoL > 0.0) {
      float lobe;
      if (uModel == 0) {
        vec3 H = L + V;
        float len = length(H);
        lobe = powGL(len > 0.0 ? dot(N, H) / len : 0.0, gl_FrontMaterial.shininess);
      } else {
        vec3 R = 2.0 * NoL * N - L;
        lobe = powGL(dot(R, V), gl_FrontMaterial.shininess);
      }
      term += lobe * gl_FrontMaterial.specular.rgb * gl_LightSource[i].specular.rgb;
    }
    c += att * spot * term;
  }
  return vec4(clamp(c, 0.0, 1.0), gl_FrontMaterial.diffuse.a);
}
)";

// Per vertex: GL's own colour path (glShadeModel, two-sided colour selection) does the rest.
const char* kPerVertexVs = R"(
void main() {
  vec3 P = vec3(gl_ModelViewMatrix * gl_Vertex);
  vec3 N = normalize(gl_NormalMatrix * gl_Normal);
  gl_FrontColor = lightGL(P, N);
  gl_BackColor = lightGL(P, -N);
  gl_Position = ftransform();
}
)";
const char* kPerVertexFs = R"(
void main() { gl_FragColor = gl_Color; }
)";

const char* kPerPixelVs = R"(
varying vec3 vP;
varying vec3 vN;
void main() {
  vP = vec3(gl_ModelViewMatrix * gl_Vertex);
  vN = normalize(gl_NormalMatrix * gl_Normal);
  gl_Position = ftransform();
}
)";
const char* kPerPixelFs = R"(
uniform bool uTwoSided;
varying vec3 vP;
varying vec3 vN;
void main() {
  vec3 N = normalize(vN);
  if (uTwoSided && !gl_FrontFacing) N = -N;
  gl_FragColor = lightGL(vP, N);
}
)";

}  // namespace

unsigned compileShader(unsigned type, const std::string& source) {
  const GLuint s = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GLSL compile error: ") + log);
  }
  return s;
}

void loadMatrix(const Mat4& m) {
  GLfloat f[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) f[c * 4 + r] = GLfloat(m[c][r]);
  glLoadMatrixf(f);
}

void setLight(unsigned id, const Light& l) {
  const GLfloat pos[4] = {GLfloat(l.position.x), GLfloat(l.position.y), GLfloat(l.position.z), GLfloat(l.position.w)};
  const GLfloat amb[4] = {GLfloat(l.ambient.r), GLfloat(l.ambient.g), GLfloat(l.ambient.b), 1};
  const GLfloat dif[4] = {GLfloat(l.diffuse.r), GLfloat(l.diffuse.g), GLfloat(l.diffuse.b), 1};
  const GLfloat spe[4] = {GLfloat(l.specular.r), GLfloat(l.specular.g), GLfloat(l.specular.b), 1};
  const GLfloat dir[3] = {GLfloat(l.spotDirection.x), GLfloat(l.spotDirection.y), GLfloat(l.spotDirection.z)};
  glEnable(id);
  glLightfv(id, GL_POSITION, pos);
  glLightfv(id, GL_AMBIENT, amb);
  glLightfv(id, GL_DIFFUSE, dif);
  glLightfv(id, GL_SPECULAR, spe);
  glLightfv(id, GL_SPOT_DIRECTION, dir);
  glLightf(id, GL_SPOT_EXPONENT, GLfloat(l.spotExponent));
  glLightf(id, GL_SPOT_CUTOFF, GLfloat(l.spotCutoff));
  glLightf(id, GL_CONSTANT_ATTENUATION, GLfloat(l.attenuation.x));
  glLightf(id, GL_LINEAR_ATTENUATION, GLfloat(l.attenuation.y));
  glLightf(id, GL_QUADRATIC_ATTENUATION, GLfloat(l.attenuation.z));
}

namespace {

GLuint buildProgram(MesaPath path) {
  const std::string header = "#version 120\n";
  const bool perPixel = path == MesaPath::GlslPerPixel;
  const GLuint program = glCreateProgram();
  glAttachShader(program, compileShader(GL_VERTEX_SHADER, header + (perPixel ? "" : kLightingGlsl) +
                                                        (perPixel ? kPerPixelVs : kPerVertexVs)));
  glAttachShader(program, compileShader(GL_FRAGMENT_SHADER, header + (perPixel ? kLightingGlsl : "") +
                                                          (perPixel ? kPerPixelFs : kPerVertexFs)));
  glLinkProgram(program);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("GLSL link error: ") + log);
  }
  return program;
}

void setMaterial(const Material& m) {
  const auto v = [](const Color4& c) { return std::vector<GLfloat>{GLfloat(c.r), GLfloat(c.g), GLfloat(c.b), GLfloat(c.a)}; };
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, v(m.ambient).data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, v(m.diffuse).data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, v(m.specular).data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, v(m.emission).data());
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, GLfloat(m.shininess));
}

}  // namespace

MesaPath mesaPathFor(const Scene& scene) {
  if (scene.shading == Shading::Phong) return MesaPath::GlslPerPixel;
  return scene.model == LightingModel::BlinnPhong ? MesaPath::FixedFunction : MesaPath::GlslPerVertex;
}

MesaSession::MesaSession(const Scene& scene, MesaPath path)
    : scene_(scene), buffer_(std::size_t(scene.width) * std::size_t(scene.height) * 4) {
  if (scene.lights.size() > 8) throw std::runtime_error("the Mesa reference takes at most 8 lights");
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) throw std::runtime_error("OSMesaCreateContextExt failed");
  context_ = ctx;
  if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, scene.width, scene.height)) {
    OSMesaDestroyContext(ctx);
    throw std::runtime_error("OSMesaMakeCurrent failed");
  }

  glViewport(0, 0, scene.width, scene.height);
  glClearColor(GLfloat(scene.background.r), GLfloat(scene.background.g), GLfloat(scene.background.b),
               GLfloat(scene.background.a));
  glClearDepth(1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_NORMALIZE);
  glShadeModel(scene.shading == Shading::Flat ? GL_FLAT : GL_SMOOTH);

  glMatrixMode(GL_PROJECTION);
  loadMatrix(scene.camera.clipFromView(GLfloat(scene.width) / GLfloat(scene.height)));
  glMatrixMode(GL_MODELVIEW);
  const Mat4 view = scene.camera.viewFromWorld();
  loadMatrix(view);
  // Lights are specified with GL_MODELVIEW = the view, so GL stores them in eye space.
  for (std::size_t i = 0; i < scene.lights.size(); ++i) setLight(GLenum(GL_LIGHT0 + i), scene.lights[i]);
  const GLfloat ambient[4] = {GLfloat(scene.lightModel.ambient.r), GLfloat(scene.lightModel.ambient.g),
                              GLfloat(scene.lightModel.ambient.b), 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, scene.lightModel.localViewer ? 1 : 0);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, scene.lightModel.twoSided ? 1 : 0);

  if (path == MesaPath::FixedFunction) {
    glEnable(GL_LIGHTING);
  } else {
    program_ = buildProgram(path);
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "uLights"), GLint(scene.lights.size()));
    glUniform1i(glGetUniformLocation(program_, "uModel"), int(scene.model));
    glUniform1i(glGetUniformLocation(program_, "uLocalViewer"), scene.lightModel.localViewer ? 1 : 0);
    if (GLint twoSided = glGetUniformLocation(program_, "uTwoSided"); twoSided >= 0)
      glUniform1i(twoSided, scene.lightModel.twoSided ? 1 : 0);
    // Per-vertex colours pick gl_BackColor on back faces only when asked, like two-sided lighting.
    if (scene.lightModel.twoSided) glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  }

  if (scene.blend) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  // Vertex colours replace the ambient and diffuse material (GL_COLOR_MATERIAL), as illum does.
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);

  // Every mesh in buffer objects once, so that a frame is only the draws (what an application does).
  for (const Object& object : scene.objects) {
    const Mesh& m = *object.mesh;
    std::vector<GLfloat> colors, uvs;
    for (const Vec4& c : m.colors) colors.insert(colors.end(), {GLfloat(c.r), GLfloat(c.g), GLfloat(c.b), GLfloat(c.a)});
    for (const Vec2& t : m.uvs) uvs.insert(uvs.end(), {GLfloat(t.x), GLfloat(t.y)});
    colors_.push_back(std::move(colors));
    uvs_.push_back(std::move(uvs));
    GLuint texture = 0;
    if (object.diffuseTexture && !m.uvs.empty()) {
      // GL_MODULATE with GL_LINEAR_MIPMAP_LINEAR and the texture's wrap modes; GL's rows run bottom to top.
      const Image image = object.diffuseTexture->baseImage();
      std::vector<std::uint8_t> rows(image.rgba.size());
      const std::size_t row = std::size_t(image.width) * 4;
      for (int y = 0; y < image.height; ++y)
        std::memcpy(&rows[std::size_t(y) * row], image.pixel(0, image.height - 1 - y), row);
      glGenTextures(1, &texture);
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      const auto wrap = [](TextureWrap w) -> GLint {
        return w == TextureWrap::MirroredRepeat ? GL_MIRRORED_REPEAT : w == TextureWrap::ClampToEdge ? GL_CLAMP_TO_EDGE : GL_REPEAT;
      };
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap(object.diffuseTexture->wraps().s));
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap(object.diffuseTexture->wraps().t));
      glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
      glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    }
    textures_.push_back(texture);
    const Mesh& mesh = *object.mesh;
    std::vector<GLfloat> interleaved;
    interleaved.reserve(mesh.positions.size() * 6);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      for (const Vec3& v : {mesh.positions[i], mesh.normals[i]})
        interleaved.insert(interleaved.end(), {GLfloat(v.x), GLfloat(v.y), GLfloat(v.z)});
    GLuint buffers[2];
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(GLfloat)), interleaved.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    meshBuffers_.push_back({buffers[0], buffers[1]});
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
}

MesaSession::~MesaSession() {
  for (GLuint t : textures_)
    if (t) glDeleteTextures(1, &t);
  for (const auto& [vertices, indices] : meshBuffers_) {
    const GLuint buffers[2] = {vertices, indices};
    glDeleteBuffers(2, buffers);
  }
  if (program_) glDeleteProgram(program_);
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void MesaSession::draw() {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const Mat4 view = scene_.camera.viewFromWorld();
  for (std::size_t k = 0; k < scene_.objects.size(); ++k) {
    const Object& object = scene_.objects[k];
    loadMatrix(view * object.worldFromObject);
    setMaterial(object.material);
    glBindBuffer(GL_ARRAY_BUFFER, meshBuffers_[k].first);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshBuffers_[k].second);
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), nullptr);
    glNormalPointer(GL_FLOAT, 6 * sizeof(GLfloat), reinterpret_cast<const void*>(3 * sizeof(GLfloat)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);  // colours and uvs from client memory
    const bool colors = !colors_[k].empty(), textured = textures_[k] != 0;
    if (colors) {
      glEnable(GL_COLOR_MATERIAL);
      glEnableClientState(GL_COLOR_ARRAY);
      glColorPointer(4, GL_FLOAT, 0, colors_[k].data());
    }
    if (textured) {
      glEnable(GL_TEXTURE_2D);
      glBindTexture(GL_TEXTURE_2D, textures_[k]);
      glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      glTexCoordPointer(2, GL_FLOAT, 0, uvs_[k].data());
    }
    glDrawElements(GL_TRIANGLES, GLsizei(object.mesh->indices.size()), GL_UNSIGNED_INT, nullptr);
    if (colors) {
      glDisableClientState(GL_COLOR_ARRAY);
      glDisable(GL_COLOR_MATERIAL);
    }
    if (textured) {
      glDisableClientState(GL_TEXTURE_COORD_ARRAY);
      glDisable(GL_TEXTURE_2D);
    }
  }
  glFinish();
}

Image MesaSession::image() const {
  // OSMesa's rows run bottom to top; images run top to bottom.
  Image image(scene_.width, scene_.height);
  const std::size_t row = std::size_t(scene_.width) * 4;
  for (int y = 0; y < scene_.height; ++y)
    std::memcpy(image.pixel(0, y), &buffer_[std::size_t(scene_.height - 1 - y) * row], row);
  return image;
}

Image renderWithMesa(const Scene& scene, MesaPath path) {
  MesaSession session(scene, path);
  session.draw();
  return session.image();
}

}  // namespace illum::test
