/*
 * eva_shade.c - Eva's driver for the shading formulas (src/render/shade.c).
 * Each call covers the whole of its function's precondition: every input is
 * the box of what the contract allows (unit directions as the box of
 * vec_normalize's bound, 4 per component).  saturating_div, scale_indices,
 * vec_length and vec_normalize are used through their contracts, checked by
 * eva_shade_split.c and eva_vec.c.
 */
#include "eva.h"
#include "render/shade.h"

volatile real eva_real;
volatile rgb eva_rgb;
volatile shade_terms eva_terms;
volatile int eva_int;

void eva_shade(void)
{
    real t = any(0, 1), n = any(0, DBL_MAX);
    eva_rgb = shade_ambient(any_coefficient(), any_colour());
    eva_rgb = shade_falloff(any_colour(), any(0, DBL_MAX), any(0, DBL_MAX), FALLOFF_LINEAR);
    eva_rgb = shade_falloff(any_colour(), any(0, DBL_MAX), any(0, DBL_MAX), FALLOFF_INVERSE_SQUARE);
    eva_rgb = shade_falloff(any_colour(), any(0, DBL_MAX), any(0, DBL_MAX), FALLOFF_NONE);
    eva_rgb = shade_sample_power(any_colour(), Frama_C_int_interval(1, 2147483647));
    eva_rgb = shade_face_forward(any_dir(), any_dir());
    eva_real = shade_lambert(any_dir(), any_dir());
    eva_rgb = shade_diffuse(any_coefficient(), any_colour(), any_dir(), any_dir());
    eva_rgb = shade_reflect_about(any_dir(), any_dir());
    eva_rgb = shade_mirror(any_dir(), any_dir());
    eva_real = shade_phong_lobe(any_vec(-1024, 1024), any_vec(-1024, 1024), n);
    eva_rgb = shade_specular(any_coefficient(), any_colour(), any_dir(), any_dir(), any_dir(), n);
    eva_terms = shade_direct(any_coefficient(), any_coefficient(), n, any_colour(), any_dir(), any_dir(), any_dir());
    vec3 out;
    eva_int = shade_refract(any_dir(), any_dir(), any(0x1p-1074, DBL_MAX), any(0x1p-1074, DBL_MAX), &out);
    eva_rgb = out;
    eva_real = shade_critical_angle_cos(any(0x1p-1074, DBL_MAX), any(0x1p-1074, DBL_MAX));
    eva_rgb = shade_transmit_blend(any_colour(), any_colour(), t);
    eva_rgb = shade_saturate(any_vec(-DBL_MAX, DBL_MAX));
    eva_rgb = shade_local(any_colour(), any_colour(), t);
    eva_rgb = shade_combine(any_colour(), any_colour(), any_coefficient(), t, any_colour(), any_colour());
    eva_real = shade_shadow_transmission(t, any(0, 1));
}
