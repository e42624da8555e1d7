// Everything a translated program includes, as one header: it is the first
// line of every generated file, so the interpreter can precompile it once.
#pragma once

#include <cmath>
#include <string>
#include <vector>

// vv 1.1 programs call OpenGL (glVertex3dv in a vertex's glRender(), the
// render blocks) without including it: every program sees GL/gl.h.
#include <GL/gl.h>

#include <util/point.hpp>

#include "plugin.hpp"
#include "translated.hpp"
#include "../vv.hpp"
