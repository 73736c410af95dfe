/* The OpenGL calls the viewer makes itself (the overlay, reading the
 * window's pixels), taken from the window's context with
 * SDL_GL_GetProcAddress: the tool links no OpenGL library. */
#ifndef MS_TOOL_VIEW_GL_H
#define MS_TOOL_VIEW_GL_H

#include <SDL_opengl.h>

/* clang-format 14 lays this list out differently on each pass: by hand */
/* clang-format off */
#define VIEW_GL_FUNCTIONS(X)                                                           \
    X(UseProgram) X(BindFramebuffer) X(Viewport) X(Disable) X(Enable) X(MatrixMode)    \
    X(LoadIdentity) X(Ortho) X(BlendFunc) X(Color4f) X(Recti) X(PixelStorei)           \
    X(WindowPos2i) X(Bitmap) X(ReadPixels) X(ReadBuffer) X(GetError) X(GetString)      \
    X(ClearColor) X(Clear) X(Finish)
/* clang-format on */

typedef struct view_gl {
    void (*UseProgram)(GLuint);
    void (*BindFramebuffer)(GLenum, GLuint);
    void (*Viewport)(GLint, GLint, GLsizei, GLsizei);
    void (*Disable)(GLenum);
    void (*Enable)(GLenum);
    void (*MatrixMode)(GLenum);
    void (*LoadIdentity)(void);
    void (*Ortho)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble);
    void (*BlendFunc)(GLenum, GLenum);
    void (*Color4f)(GLfloat, GLfloat, GLfloat, GLfloat);
    void (*Recti)(GLint, GLint, GLint, GLint);
    void (*PixelStorei)(GLenum, GLint);
    void (*WindowPos2i)(GLint, GLint);
    void (*Bitmap)(GLsizei, GLsizei, GLfloat, GLfloat, GLfloat, GLfloat, const GLubyte *);
    void (*ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *);
    void (*ReadBuffer)(GLenum);
    GLenum (*GetError)(void);
    const GLubyte *(*GetString)(GLenum);
    void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
    void (*Clear)(GLbitfield);
    void (*Finish)(void);
} view_gl;

extern view_gl view_gl_fn;
/* Takes the calls from the current context; -1 if one is missing. */
int view_gl_load(void);
/* Text (lines split by '\n') in a box at the window's top left (top = 1)
 * or bottom left (top = 0), over what is drawn. */
void view_overlay_draw(const char *text, int w, int h, int top);

#endif
