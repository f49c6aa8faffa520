/* SPDX-License-Identifier: MIT */
/* fixel's own <GL/glut.h> (boards/glut): GLUT on fixel framebuffers. As
 * freeglut's, it brings the freeglut extensions too. */
#ifndef FIXEL_GL_GLUT_H
#define FIXEL_GL_GLUT_H
#define __GLUT_H__
#include <GL/freeglut_std.h>
#include <GL/freeglut_ext.h>
#endif
