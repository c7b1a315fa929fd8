/*
** dim.h - the one place that fixes the spatial dimension.
** Everything else loops over DIM; a 3-D build is -DDIM=3.
*/
#ifndef mvmpm_dim_h
#define mvmpm_dim_h

#ifndef DIM
#define DIM 2
#endif

#if DIM == 2
/* plane strain: in-plane xx, yy, xy plus the out-of-plane zz that
** eps_zz = 0 produces; zz does not enter the in-plane forces */
#define NSTRESS 4
enum { S_XX, S_YY, S_XY, S_ZZ };
#define DIM_STRESS_NAMES {"xx", "yy", "xy", "zz"}
#define DIM_TENSOR_NAMES {"xx", "xy", "yx", "yy"}
#define DIM_VOLUME_UNIT "L^2"
#elif DIM == 3
#define NSTRESS 6
enum { S_XX, S_YY, S_ZZ, S_XY, S_YZ, S_XZ };
#define DIM_STRESS_NAMES {"xx", "yy", "zz", "xy", "yz", "xz"}
#define DIM_TENSOR_NAMES {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"}
#define DIM_VOLUME_UNIT "L^3"
#else
#error "DIM must be 2 or 3"
#endif

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define NTENS (DIM * DIM) /* full (unsymmetric) tensors: F, grad v */

#endif
