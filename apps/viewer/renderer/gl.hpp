// The viewer's OpenGL entry points: libepoxy, included here and nowhere else in the viewer.
#pragma once

#include <epoxy/gl.h>
