/*
 * kit_readme.c - the README.md of a conformance kit: one page for the
 * author of another renderer, then the table of the kit's scenes.  The
 * rule stated here is the one conform applies (spec/conformance.md
 * [KIT-RULE-1]); the tests hold both to it.
 */
#include <stdio.h>
#include "io/filewrite.h"
#include "verify/kit.h"

/* The page in sections (C99 guarantees string literals only up to 4095 bytes). */
static const char *const readme_head[] = {
    "This directory checks a renderer against exact images.  Every scene in it has an image known\n"
    "in closed form (derived in refray's spec/analytic.md), evaluated at the very points a Whitted\n"
    "ray tracer samples.  Render a scene, compare your image with the exact one under the tolerance\n"
    "of `manifest.json`, and you know pixel by pixel whether your renderer computes the same model.\n"
    "Nothing here needs refray: the images, masks and tolerances are plain files.\n"
    "\n"
    "## What is here\n"
    "\n"
    "    manifest.json                  every scene: files, settings, tolerance, peak, scale, conventions\n"
    "    scenes/NAME/NAME.scene         the scene in refray's scene language\n"
    "    scenes/NAME/NAME.json          the same scene with every value explicit (when listed)\n"
    "    scenes/NAME/NAME.pov           the same scene for POV-Ray 3.7, lights scaled by png16_scale\n"
    "    scenes/NAME/NAME.exact.exr     the exact image: linear RGB, 32-bit float OpenEXR\n"
    "    scenes/NAME/NAME.exact.pfm     the same as PFM\n"
    "    scenes/NAME/NAME.mask.pgm      pixels not compared: 255 excluded, 0 compared (8-bit PGM)\n"
    "    scenes/NAME/NAME.mask.png      the same as an 8-bit PNG\n"
    "\n"
    "A file the manifest lists as null is missing for the reason under `missing`.\n"
    "\n",
    "## Rendering a scene\n"
    "\n"
    "Read the `.json` (or the `.scene`; or render the `.pov` with POV-Ray) and render `width` x\n"
    "`height` pixels:\n"
    "\n"
    "- Linear RGB: no gamma, no tone curve, no clamping; values above 1 stay.  Row 0 is the top row.\n"
    "- Pixel (i, j) is the mean radiance at the k x k points (i + (a + 0.5)/k, j + (b + 0.5)/k),\n"
    "  a, b = 0 .. k-1, k = `samples`, in image coordinates (x right, y down, the picture spans\n"
    "  [0, width] x [0, height]).  No jitter, no other filter.  A renderer that shoots one ray\n"
    "  through each pixel centre renders k*width x k*height and has the k x k blocks averaged.\n"
    "- The shading model and its conventions (depth counting, falloff, transparency t, shadows,\n"
    "  total internal reflection, distributed lights) are listed under `conventions` in the\n"
    "  manifest.  No 1/pi anywhere: a Lambert surface under a point light is Kd E cos / falloff.\n"
    "- Write a 32-bit float EXR or PFM; or a 16-bit PNG with linear codes after multiplying every\n"
    "  light, the ambient light and the background by the scene's `png16_scale` (then divide the\n"
    "  image by it; the `.pov` files are already scaled).  Half-float EXR (a relative step of\n"
    "  4.9e-4) and 8-bit PNG are too coarse for the tolerance.\n"
    "\n",
    "## Checking without refray\n"
    "\n"
    "Read your image OUT and the exact image EXACT (same size; PFM rows run bottom to top), and the\n"
    "mask.  For every pixel the mask does not mark (0) and every channel c, the channel fails when\n"
    "|OUT_c - EXACT_c| > relative * |EXACT_c| + absolute, with `tolerance.relative` and\n"
    "`tolerance.absolute` of the scene in the manifest (a NaN or an infinity fails).  The scene\n"
    "passes when no channel fails and at least one pixel was compared.  `relative` is 1e-4 for\n"
    "deterministic families and the family's sampling bound for distributed lights; `absolute` is\n"
    "2^-20 of the peak for a float picture (PFM, EXR); a PNG is judged with `absolute_png`\n"
    "instead, one step of a 16-bit PNG at the scene's scale, 1 / (65535 png16_scale).  Report max |OUT -\n"
    "EXACT|, the RMS over all compared channels and the largest |OUT - EXACT| / |EXACT| to see how\n"
    "close you are.  Sampled scenes (`sampled` true) converge as `expected_order` says when your\n"
    "renderer takes more light samples.  The same rule as one C99 file without any library (PFM\n"
    "and PGM only): `kit_check.c` in the tarball of `make kit`, or tests/conform/kit_check.c in the\n"
    "refray sources.\n"
    "\n",
    "## Checking with refray\n"
    "\n"
    "    refray conform --kit DIR --format exr --cmd '/path/to/myrenderer {json} -o {out}'\n"
    "    refray compare mine.exr --manifest DIR/manifest.json --scene NAME\n"
    "\n"
    "`conform` runs the command once per scene through /bin/sh in a fresh directory (so name\n"
    "programs by absolute path), with the placeholders `{scene}` `{json}` `{pov}` `{out}`\n"
    "`{width}` `{height}` `{samples}` `{name}` `{scale}` replaced by shell-quoted values (do\n"
    "not quote them again), with a time limit, and prints one row per scene (`--json`,\n"
    "`--junit FILE`, `--tap` for CI).  POV-Ray 3.7 over the whole kit:\n"
    "\n"
    "    refray conform --kit DIR --format png --downsample manifest --scale manifest \\\n"
    "        --cmd 'cp {pov} s.pov && povray +Is.pov +Oo.png +W{width} +H{height} -A -D -V +WT1 \\\n"
    "               +FN16 File_Gamma=1.0 Output_Alpha=off && mv o.png {out}'\n"
    "\n"
    "See refray's spec/conformance.md for everything here in detail.\n"
    "\n",
    "## The scenes\n"
    "\n"
    "| scene | family | width x height | samples | max_depth | relative | absolute | peak | masked | "
    "png16_scale |\n"
    "|---|---|---|---|---|---|---|---|---|---|\n",
};

static int fill(FILE *fp, void *ctx)
{
    const manifest *m = ctx;
    fprintf(fp, "# refray conformance kit%s%s\n\n", m->refray_version[0] ? " " : "", m->refray_version);
    for (size_t i = 0; i < sizeof readme_head / sizeof readme_head[0]; i++)
        fputs(readme_head[i], fp);
    for (int i = 0; i < m->scene_count; i++) {
        const manifest_scene *s = &m->scenes[i];
        fprintf(fp, "| %s | %s | %dx%d | %d | %d | %.3g | %.3g | %.4g | %ld | %.17g |\n", s->name, s->family,
                s->width, s->height, s->samples, s->max_depth, s->relative, s->absolute, s->peak, s->masked,
                s->png16_scale);
    }
    return ferror(fp) ? STATUS_IO : STATUS_OK;
}

int kit_readme_write(const char *path, const manifest *m, char *why, size_t why_size)
{
    return file_write_atomic(path, fill, (void *)m, why, why_size);
}
