#!/usr/bin/env python3
"""mutants.py NAME SRC DST - attack 24h: writes src/render/trace.c with the
[SHADE-SHORTCUT-HIDDEN-1] mutant NAME applied (SRC pristine, DST written);
exit 2 when the text to mutate is not found exactly once.  `list`: names."""
import sys
M = {
    'factor1': ('u = vec_scale(u, 2);', 'u = vec_scale(u, 1);'),
    'factorhalf': ('u = vec_scale(u, 2);', 'u = vec_scale(u, 0.5);'),
    'nosamples': ('vec_scale(one, (real)light_loop_samples(t, i))', 'one'),
    'nomargin': ('m_len * (cos_t * cos_a + sin_t * sin_a) + 0x1p-20', 'm_len * (cos_t * cos_a + sin_t * sin_a)'),
    'farside': ('gap * (1 - 0x1p-20)', '(gap + 2 * reach)'),
    'thetaplus': ('cos_t * cos_a + sin_t * sin_a', 'cos_t * cos_a - sin_t * sin_a'),
    'distnomargin': ('vec_dot(l, m) + 0x1p-20, s->m->n', 'vec_dot(l, m), s->m->n'),
    'redonly': ('return lo.x == hi.x && lo.y == hi.y && lo.z == hi.z;', 'return lo.x == hi.x;'),
    'nomlen': ('return m_len * (cos_t', 'return (cos_t'),
    'noreach': ('trace_lobe_above(trace_ball_cosine_above(d, reach, m)', 'trace_lobe_above(trace_ball_cosine_above(d, 0, m)'),
    'distzero': ('if (light->kind == LIGHT_DISTANT) {\n        vec3 l', 'if (light->kind == LIGHT_DISTANT) {\n        return vec_splat(0);\n        vec3 l'),
    'nosize': ('    if (!(gap >= 0x1p-16 * size && gap >= 0x1p-400))\n        return none;\n    rgb i', '    rgb i'),
    'nocount': ('st->light_samples += light_loop_samples(t, i);', ''),
    'noclamp': ('u = vec_make(u.x < DBL_MAX ? u.x : DBL_MAX, u.y < DBL_MAX ? u.y : DBL_MAX, u.z < DBL_MAX ? u.z : DBL_MAX);', ''),
    'lobe2n': ('trace_ball_cosine_above(d, reach, m), s->m->n)', 'trace_ball_cosine_above(d, reach, m), 2 * s->m->n)'),
    'nocancel': ('            cancel_steps(st->cancel, t->lights[i].samples);', '            (void)0;'),
    'pointreach': ('real reach = point ? 0 : setup->reach;', 'real reach = point ? 0 : 0.5 * setup->reach;'),
    'mirrorless': ('rgb hi = shade_combine(body, u, s->m->ks, s->m->t, mirror, through);', 'rgb hi = shade_combine(body, u, s->m->ks, s->m->t, mirror, vec_splat(0));'),
}
if sys.argv[1] == 'list':
    print(' '.join(M)); sys.exit(0)
a, b = M[sys.argv[1]]
s = open(sys.argv[2]).read()
if s.count(a) != 1:
    print('mutant %s: %d matches' % (sys.argv[1], s.count(a))); sys.exit(2)
open(sys.argv[3], 'w').write(s.replace(a, b))
