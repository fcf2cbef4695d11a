/*
 * eva.h - inputs for Eva's drivers (tests/prove/eva_*.c): each returns any
 * double, vector or colour of a box, so that a driver's call covers a
 * whole domain at once.  Analysis only: never compiled into refray.
 */
#ifndef REFRAY_PROVE_EVA_H
#define REFRAY_PROVE_EVA_H

#include "__fc_builtin.h"
#include "base/vec.h"

static real any(real lo, real hi) { return Frama_C_double_interval(lo, hi); }
static vec3 any_vec(real lo, real hi) { return vec_make(any(lo, hi), any(lo, hi), any(lo, hi)); }
/* What a unit vector is to Eva: vec_normalize's bound. */
static vec3 any_dir(void) { return any_vec(-4, 4); }
static rgb any_colour(void) { return any_vec(0, DBL_MAX); }
static rgb any_coefficient(void) { return any_vec(0, 1); }

#endif
