/*
** cmap.h - colours for data: two continuous colormaps and a
** categorical palette.
**   CMAP_SEQ  dark indigo -> blue -> teal -> green -> yellow; lightness
**             rises all the way, so the order reads in grey too
**   CMAP_DIV  blue -> light grey -> red, for signed data centred on 0;
**             the middle is grey, not white, so that particles near zero
**             still stand out from a white background
** Both interpolate linearly in RGB between five stops.
*/
#ifndef mvmpm_cmap_h
#define mvmpm_cmap_h

#include <stdint.h>

enum { CMAP_SEQ, CMAP_DIV };
#define CMAP_NAN 0x808080u   /* the colour of a value that is NaN */
#define CMAP_NCAT 10         /* categorical colours before they repeat */

/* colour of t in [0, 1] (clamped) on map */
uint32_t cmap_color(int map, double t);
/* colour k of the categorical palette (k >= 0; cycles); none is grey */
uint32_t cmap_category(int k);

#endif
