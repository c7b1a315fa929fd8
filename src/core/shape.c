/*
** shape.c - names of the shape functions (the weights are inline in
** shape.h, where the hot loops can fold them).
*/
#include <stddef.h>
#include "shape.h"

const char *const shape_names[] = {"linear", "gimp", "bspline2", NULL};
