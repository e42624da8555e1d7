// Everything a translated program includes, as one header: it is the first
// line of every generated file, so the interpreter can precompile it once.
// The model layer (this folder) sits on the algebra (vv/) and is the only
// part of vvlib that knows of a host: the model object (program.hpp), the
// proxy, the file-object registry, the plugin ABI and its entry points.
// OpenGL is not included here: the generated program includes <GL/gl.h>
// itself (programs see the GL API without including it).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <util/point.hpp>
#include <vv/vv.hpp>

#include "abi.hpp"
#include "entry_points.hpp"
#include "program.hpp"
#include "proxy.hpp"
#include "translated.hpp"
