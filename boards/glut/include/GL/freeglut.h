/* SPDX-License-Identifier: MIT */
/* fixel's own <GL/freeglut.h> (boards/glut). */
#ifndef FIXEL_GL_FREEGLUT_H
#define FIXEL_GL_FREEGLUT_H
#define __FREEGLUT_H__
#include <GL/freeglut_std.h>
#include <GL/freeglut_ext.h>
#endif
