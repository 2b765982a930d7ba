/* SPDX-License-Identifier: MIT */
/*
** iris.h: the umbrella header of libiris.
**
** common.h has the version, status codes and allocator; scene.h the
** plain-data scene description; fn.h compiled SDL functions; parse.h the
** SDL front end; image.h image files; render.h rendering.
*/
#ifndef IRIS_IRIS_H
#define IRIS_IRIS_H

#include "iris/common.h"
#include "iris/scene.h"
#include "iris/fn.h"
#include "iris/parse.h"
#include "iris/image.h"
#include "iris/render.h"

#endif
