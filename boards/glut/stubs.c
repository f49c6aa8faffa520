/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — the calls declared in fixel's GL headers that the
 * layer does not implement: each records GL_INVALID_OPERATION for glGetError
 * and logs its name once. Written by hand from the headers (no generator:
 * docs/RECIPES.md says how a call moves out of this file); gl-corners, whose
 * table is generated from the headers, calls every one of them. */
#include "glut_int.h"

void glEdgeFlag(GLboolean flag)
{
    (void)flag;
    fx_glut_unimplemented("glEdgeFlag", GL_INVALID_OPERATION);
}

void glIndexi(GLint c)
{
    (void)c;
    fx_glut_unimplemented("glIndexi", GL_INVALID_OPERATION);
}

void glIndexf(GLfloat c)
{
    (void)c;
    fx_glut_unimplemented("glIndexf", GL_INVALID_OPERATION);
}

void glClearIndex(GLfloat c)
{
    (void)c;
    fx_glut_unimplemented("glClearIndex", GL_INVALID_OPERATION);
}

void glClearStencil(GLint s)
{
    (void)s;
    fx_glut_unimplemented("glClearStencil", GL_INVALID_OPERATION);
}

void glClearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a)
{
    (void)r;
    (void)g;
    (void)b;
    (void)a;
    fx_glut_unimplemented("glClearAccum", GL_INVALID_OPERATION);
}

void glPolygonStipple(const GLubyte *mask)
{
    (void)mask;
    fx_glut_unimplemented("glPolygonStipple", GL_INVALID_OPERATION);
}

void glEnableClientState(GLenum cap)
{
    (void)cap;
    fx_glut_unimplemented("glEnableClientState", GL_INVALID_OPERATION);
}

void glDisableClientState(GLenum cap)
{
    (void)cap;
    fx_glut_unimplemented("glDisableClientState", GL_INVALID_OPERATION);
}

void glAlphaFunc(GLenum func, GLclampf ref)
{
    (void)func;
    (void)ref;
    fx_glut_unimplemented("glAlphaFunc", GL_INVALID_OPERATION);
}

void glLogicOp(GLenum opcode)
{
    (void)opcode;
    fx_glut_unimplemented("glLogicOp", GL_INVALID_OPERATION);
}

void glStencilFunc(GLenum func, GLint ref, GLuint mask)
{
    (void)func;
    (void)ref;
    (void)mask;
    fx_glut_unimplemented("glStencilFunc", GL_INVALID_OPERATION);
}

void glStencilOp(GLenum fail, GLenum zfail, GLenum zpass)
{
    (void)fail;
    (void)zfail;
    (void)zpass;
    fx_glut_unimplemented("glStencilOp", GL_INVALID_OPERATION);
}

void glStencilMask(GLuint mask)
{
    (void)mask;
    fx_glut_unimplemented("glStencilMask", GL_INVALID_OPERATION);
}

void glFogf(GLenum pname, GLfloat param)
{
    (void)pname;
    (void)param;
    fx_glut_unimplemented("glFogf", GL_INVALID_OPERATION);
}

void glFogi(GLenum pname, GLint param)
{
    (void)pname;
    (void)param;
    fx_glut_unimplemented("glFogi", GL_INVALID_OPERATION);
}

void glFogfv(GLenum pname, const GLfloat *params)
{
    (void)pname;
    (void)params;
    fx_glut_unimplemented("glFogfv", GL_INVALID_OPERATION);
}

void glFogiv(GLenum pname, const GLint *params)
{
    (void)pname;
    (void)params;
    fx_glut_unimplemented("glFogiv", GL_INVALID_OPERATION);
}

void glAccum(GLenum op, GLfloat value)
{
    (void)op;
    (void)value;
    fx_glut_unimplemented("glAccum", GL_INVALID_OPERATION);
}

void glClipPlane(GLenum plane, const GLdouble *equation)
{
    (void)plane;
    (void)equation;
    fx_glut_unimplemented("glClipPlane", GL_INVALID_OPERATION);
}

void glTexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei w, GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    (void)target;
    (void)level;
    (void)internalformat;
    (void)w;
    (void)border;
    (void)format;
    (void)type;
    (void)pixels;
    fx_glut_unimplemented("glTexImage1D", GL_INVALID_OPERATION);
}

void glTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, const GLvoid *pixels)
{
    (void)target;
    (void)level;
    (void)x;
    (void)y;
    (void)w;
    (void)h;
    (void)format;
    (void)type;
    (void)pixels;
    fx_glut_unimplemented("glTexSubImage2D", GL_INVALID_OPERATION);
}

void glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei w, GLsizei h, GLint border)
{
    (void)target;
    (void)level;
    (void)internalformat;
    (void)x;
    (void)y;
    (void)w;
    (void)h;
    (void)border;
    fx_glut_unimplemented("glCopyTexImage2D", GL_INVALID_OPERATION);
}

void glTexGeni(GLenum coord, GLenum pname, GLint param)
{
    (void)coord;
    (void)pname;
    (void)param;
    fx_glut_unimplemented("glTexGeni", GL_INVALID_OPERATION);
}

void glTexGenfv(GLenum coord, GLenum pname, const GLfloat *params)
{
    (void)coord;
    (void)pname;
    (void)params;
    fx_glut_unimplemented("glTexGenfv", GL_INVALID_OPERATION);
}

void glCopyPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type)
{
    (void)x;
    (void)y;
    (void)w;
    (void)h;
    (void)type;
    fx_glut_unimplemented("glCopyPixels", GL_INVALID_OPERATION);
}

void glPushAttrib(GLbitfield mask)
{
    (void)mask;
    fx_glut_unimplemented("glPushAttrib", GL_INVALID_OPERATION);
}

void glPopAttrib(void)
{
    fx_glut_unimplemented("glPopAttrib", GL_INVALID_OPERATION);
}

GLint glRenderMode(GLenum mode)
{
    (void)mode;
    fx_glut_unimplemented("glRenderMode", GL_INVALID_OPERATION);
    return 0;
}

void glInitNames(void)
{
    fx_glut_unimplemented("glInitNames", GL_INVALID_OPERATION);
}

void glLoadName(GLuint name)
{
    (void)name;
    fx_glut_unimplemented("glLoadName", GL_INVALID_OPERATION);
}

void glPushName(GLuint name)
{
    (void)name;
    fx_glut_unimplemented("glPushName", GL_INVALID_OPERATION);
}

void glPopName(void)
{
    fx_glut_unimplemented("glPopName", GL_INVALID_OPERATION);
}

void glSelectBuffer(GLsizei size, GLuint *buffer)
{
    (void)size;
    (void)buffer;
    fx_glut_unimplemented("glSelectBuffer", GL_INVALID_OPERATION);
}

void glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    (void)size;
    (void)type;
    (void)stride;
    (void)ptr;
    fx_glut_unimplemented("glVertexPointer", GL_INVALID_OPERATION);
}

void glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    (void)size;
    (void)type;
    (void)stride;
    (void)ptr;
    fx_glut_unimplemented("glColorPointer", GL_INVALID_OPERATION);
}

void glNormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    (void)type;
    (void)stride;
    (void)ptr;
    fx_glut_unimplemented("glNormalPointer", GL_INVALID_OPERATION);
}

void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    (void)size;
    (void)type;
    (void)stride;
    (void)ptr;
    fx_glut_unimplemented("glTexCoordPointer", GL_INVALID_OPERATION);
}

void glArrayElement(GLint i)
{
    (void)i;
    fx_glut_unimplemented("glArrayElement", GL_INVALID_OPERATION);
}

void glDrawArrays(GLenum mode, GLint first, GLsizei count)
{
    (void)mode;
    (void)first;
    (void)count;
    fx_glut_unimplemented("glDrawArrays", GL_INVALID_OPERATION);
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
    (void)mode;
    (void)count;
    (void)type;
    (void)indices;
    fx_glut_unimplemented("glDrawElements", GL_INVALID_OPERATION);
}

void glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order, const GLfloat *points)
{
    (void)target;
    (void)u1;
    (void)u2;
    (void)stride;
    (void)order;
    (void)points;
    fx_glut_unimplemented("glMap1f", GL_INVALID_OPERATION);
}

void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat *points)
{
    (void)target;
    (void)u1;
    (void)u2;
    (void)ustride;
    (void)uorder;
    (void)v1;
    (void)v2;
    (void)vstride;
    (void)vorder;
    (void)points;
    fx_glut_unimplemented("glMap2f", GL_INVALID_OPERATION);
}

void glEvalCoord1f(GLfloat u)
{
    (void)u;
    fx_glut_unimplemented("glEvalCoord1f", GL_INVALID_OPERATION);
}

void glEvalCoord2f(GLfloat u, GLfloat v)
{
    (void)u;
    (void)v;
    fx_glut_unimplemented("glEvalCoord2f", GL_INVALID_OPERATION);
}

void glMapGrid1f(GLint un, GLfloat u1, GLfloat u2)
{
    (void)un;
    (void)u1;
    (void)u2;
    fx_glut_unimplemented("glMapGrid1f", GL_INVALID_OPERATION);
}

void glMapGrid2f(GLint un, GLfloat u1, GLfloat u2, GLint vn, GLfloat v1, GLfloat v2)
{
    (void)un;
    (void)u1;
    (void)u2;
    (void)vn;
    (void)v1;
    (void)v2;
    fx_glut_unimplemented("glMapGrid2f", GL_INVALID_OPERATION);
}

void glEvalMesh1(GLenum mode, GLint i1, GLint i2)
{
    (void)mode;
    (void)i1;
    (void)i2;
    fx_glut_unimplemented("glEvalMesh1", GL_INVALID_OPERATION);
}

void glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2)
{
    (void)mode;
    (void)i1;
    (void)i2;
    (void)j1;
    (void)j2;
    fx_glut_unimplemented("glEvalMesh2", GL_INVALID_OPERATION);
}

void gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint *viewport)
{
    (void)x;
    (void)y;
    (void)delX;
    (void)delY;
    (void)viewport;
    fx_glut_unimplemented("gluPickMatrix", GL_INVALID_OPERATION);
}

GLint gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble *model, const GLdouble *proj, const GLint *view, GLdouble *winX, GLdouble *winY, GLdouble *winZ)
{
    (void)objX;
    (void)objY;
    (void)objZ;
    (void)model;
    (void)proj;
    (void)view;
    (void)winX;
    (void)winY;
    (void)winZ;
    fx_glut_unimplemented("gluProject", GL_INVALID_OPERATION);
    return 0;
}

GLint gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble *model, const GLdouble *proj, const GLint *view, GLdouble *objX, GLdouble *objY, GLdouble *objZ)
{
    (void)winX;
    (void)winY;
    (void)winZ;
    (void)model;
    (void)proj;
    (void)view;
    (void)objX;
    (void)objY;
    (void)objZ;
    fx_glut_unimplemented("gluUnProject", GL_INVALID_OPERATION);
    return 0;
}

const GLubyte * gluErrorString(GLenum error)
{
    (void)error;
    fx_glut_unimplemented("gluErrorString", GL_INVALID_OPERATION);
    return 0;
}

const GLubyte * gluGetString(GLenum name)
{
    (void)name;
    fx_glut_unimplemented("gluGetString", GL_INVALID_OPERATION);
    return 0;
}

GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height, GLenum format, GLenum type, const void *data)
{
    (void)target;
    (void)internalFormat;
    (void)width;
    (void)height;
    (void)format;
    (void)type;
    (void)data;
    fx_glut_unimplemented("gluBuild2DMipmaps", GL_INVALID_OPERATION);
    return 0;
}

void glutEstablishOverlay(void)
{
    fx_glut_unimplemented("glutEstablishOverlay", GL_INVALID_OPERATION);
}

void glutRemoveOverlay(void)
{
    fx_glut_unimplemented("glutRemoveOverlay", GL_INVALID_OPERATION);
}

void glutUseLayer(GLenum layer)
{
    (void)layer;
    fx_glut_unimplemented("glutUseLayer", GL_INVALID_OPERATION);
}

void glutPostOverlayRedisplay(void)
{
    fx_glut_unimplemented("glutPostOverlayRedisplay", GL_INVALID_OPERATION);
}

void glutShowOverlay(void)
{
    fx_glut_unimplemented("glutShowOverlay", GL_INVALID_OPERATION);
}

void glutHideOverlay(void)
{
    fx_glut_unimplemented("glutHideOverlay", GL_INVALID_OPERATION);
}

void glutJoystickFunc(void (*callback)(unsigned int, int, int, int), int pollInterval)
{
    (void)callback;
    (void)pollInterval;
    fx_glut_unimplemented("glutJoystickFunc", GL_INVALID_OPERATION);
}

void glutOverlayDisplayFunc(void (*callback)(void))
{
    (void)callback;
    fx_glut_unimplemented("glutOverlayDisplayFunc", GL_INVALID_OPERATION);
}

void glutSpaceballMotionFunc(void (*callback)(int, int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutSpaceballMotionFunc", GL_INVALID_OPERATION);
}

void glutSpaceballRotateFunc(void (*callback)(int, int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutSpaceballRotateFunc", GL_INVALID_OPERATION);
}

void glutSpaceballButtonFunc(void (*callback)(int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutSpaceballButtonFunc", GL_INVALID_OPERATION);
}

void glutButtonBoxFunc(void (*callback)(int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutButtonBoxFunc", GL_INVALID_OPERATION);
}

void glutDialsFunc(void (*callback)(int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutDialsFunc", GL_INVALID_OPERATION);
}

void glutTabletMotionFunc(void (*callback)(int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutTabletMotionFunc", GL_INVALID_OPERATION);
}

void glutTabletButtonFunc(void (*callback)(int, int, int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutTabletButtonFunc", GL_INVALID_OPERATION);
}

void glutGameModeString(const char *string)
{
    (void)string;
    fx_glut_unimplemented("glutGameModeString", GL_INVALID_OPERATION);
}

int glutEnterGameMode(void)
{
    fx_glut_unimplemented("glutEnterGameMode", GL_INVALID_OPERATION);
    return 0;
}

void glutLeaveGameMode(void)
{
    fx_glut_unimplemented("glutLeaveGameMode", GL_INVALID_OPERATION);
}

int glutGameModeGet(GLenum query)
{
    (void)query;
    fx_glut_unimplemented("glutGameModeGet", GL_INVALID_OPERATION);
    return 0;
}

void glutSetColor(int color, GLfloat red, GLfloat green, GLfloat blue)
{
    (void)color;
    (void)red;
    (void)green;
    (void)blue;
    fx_glut_unimplemented("glutSetColor", GL_INVALID_OPERATION);
}

GLfloat glutGetColor(int color, int component)
{
    (void)color;
    (void)component;
    fx_glut_unimplemented("glutGetColor", GL_INVALID_OPERATION);
    return 0;
}

void glutCopyColormap(int window)
{
    (void)window;
    fx_glut_unimplemented("glutCopyColormap", GL_INVALID_OPERATION);
}

void glutForceJoystickFunc(void)
{
    fx_glut_unimplemented("glutForceJoystickFunc", GL_INVALID_OPERATION);
}

void glutPositionFunc(void (*callback)(int, int))
{
    (void)callback;
    fx_glut_unimplemented("glutPositionFunc", GL_INVALID_OPERATION);
}

void glutMenuDestroyFunc(void (*callback)(void))
{
    (void)callback;
    fx_glut_unimplemented("glutMenuDestroyFunc", GL_INVALID_OPERATION);
}

int * glutGetModeValues(GLenum mode, int *size)
{
    (void)mode;
    (void)size;
    fx_glut_unimplemented("glutGetModeValues", GL_INVALID_OPERATION);
    return 0;
}

void * glutGetWindowData(void)
{
    fx_glut_unimplemented("glutGetWindowData", GL_INVALID_OPERATION);
    return 0;
}

void glutSetWindowData(void *data)
{
    (void)data;
    fx_glut_unimplemented("glutSetWindowData", GL_INVALID_OPERATION);
}

void * glutGetMenuData(void)
{
    fx_glut_unimplemented("glutGetMenuData", GL_INVALID_OPERATION);
    return 0;
}

void glutSetMenuData(void *data)
{
    (void)data;
    fx_glut_unimplemented("glutSetMenuData", GL_INVALID_OPERATION);
}

void glutWireRhombicDodecahedron(void)
{
    fx_glut_unimplemented("glutWireRhombicDodecahedron", GL_INVALID_OPERATION);
}

void glutSolidRhombicDodecahedron(void)
{
    fx_glut_unimplemented("glutSolidRhombicDodecahedron", GL_INVALID_OPERATION);
}

void glutWireSierpinskiSponge(int num_levels, double offset[3], double scale)
{
    (void)num_levels;
    (void)offset;
    (void)scale;
    fx_glut_unimplemented("glutWireSierpinskiSponge", GL_INVALID_OPERATION);
}

void glutSolidSierpinskiSponge(int num_levels, double offset[3], double scale)
{
    (void)num_levels;
    (void)offset;
    (void)scale;
    fx_glut_unimplemented("glutSolidSierpinskiSponge", GL_INVALID_OPERATION);
}

void glutWireTeacup(double size)
{
    (void)size;
    fx_glut_unimplemented("glutWireTeacup", GL_INVALID_OPERATION);
}

void glutSolidTeacup(double size)
{
    (void)size;
    fx_glut_unimplemented("glutSolidTeacup", GL_INVALID_OPERATION);
}

void glutWireTeaspoon(double size)
{
    (void)size;
    fx_glut_unimplemented("glutWireTeaspoon", GL_INVALID_OPERATION);
}

void glutSolidTeaspoon(double size)
{
    (void)size;
    fx_glut_unimplemented("glutSolidTeaspoon", GL_INVALID_OPERATION);
}

void glutInitContextVersion(int majorVersion, int minorVersion)
{
    (void)majorVersion;
    (void)minorVersion;
    fx_glut_unimplemented("glutInitContextVersion", GL_INVALID_OPERATION);
}

void glutInitContextFlags(int flags)
{
    (void)flags;
    fx_glut_unimplemented("glutInitContextFlags", GL_INVALID_OPERATION);
}

void glutInitContextProfile(int profile)
{
    (void)profile;
    fx_glut_unimplemented("glutInitContextProfile", GL_INVALID_OPERATION);
}

void glutInitErrorFunc(void (*callback)(const char *fmt, va_list ap))
{
    (void)callback;
    fx_glut_unimplemented("glutInitErrorFunc", GL_INVALID_OPERATION);
}

void glutInitWarningFunc(void (*callback)(const char *fmt, va_list ap))
{
    (void)callback;
    fx_glut_unimplemented("glutInitWarningFunc", GL_INVALID_OPERATION);
}
