// The OpenGL 3.3 core entry points the renderer uses, resolved from the current context
// (GlContext::proc_address) into one table per renderer. Nothing links libGL: the table is the
// only way the renderer reaches OpenGL, so the binary loads without any GL library.
#pragma once
#include <string>

#include <GL/glcorearb.h>

#include "gpu/gl/gl_context.h"

namespace psx::gpu::gl {

#define PSXRL_GL_FUNCTIONS(X)                                                                      \
  X(PFNGLGETERRORPROC, GetError)                                                                   \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                             \
  X(PFNGLVIEWPORTPROC, Viewport)                                                                   \
  X(PFNGLDISABLEPROC, Disable)                                                                     \
  X(PFNGLENABLEPROC, Enable)                                                                       \
  X(PFNGLSCISSORPROC, Scissor)                                                                     \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                             \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                                             \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                       \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                                             \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                               \
  X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                         \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                     \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                               \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                     \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                           \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                       \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                                     \
  X(PFNGLCLEARBUFFERUIVPROC, ClearBufferuiv)                                                       \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                                               \
  X(PFNGLCREATESHADERPROC, CreateShader)                                                           \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                                           \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                           \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                                         \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                             \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                                   \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                         \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                         \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                                           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                             \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                           \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                 \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                                               \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                               \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                                                 \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                     \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                               \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                     \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                                               \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                         \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                                               \
  X(PFNGLBUFFERDATAPROC, BufferData)                                                               \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                     \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)                                           \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                                             \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                               \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)

struct GlFunctions {
#define PSXRL_GL_MEMBER(type, name) type name = nullptr;
  PSXRL_GL_FUNCTIONS(PSXRL_GL_MEMBER)
#undef PSXRL_GL_MEMBER

  // Resolves every entry point from the current context; false with `error` naming the first
  // one missing.
  bool load(GlContext& context, std::string& error);
};

}  // namespace psx::gpu::gl
