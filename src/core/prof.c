/*
** prof.c - what `mvmpm run --profile` prints: the effects the engine
** derived from the scene (what each step does), and the wall time per
** phase with its share.
*/
#include <math.h>
#include <stdio.h>
#include "prof.h"
#include "heat.h"
#include "sim.h"

const char *const prof_names[PROF_N] = {
    "p2g (incl. grid reset, marking)", "grid solve",
    "contact (normals, reach, bonds)", "sides, driven bodies", "g2p",
    "MUSL remap", "constitutive (incl. thermal)",
    "heat (friction heat, conduction, T)", "housekeeping (dt, sort)",
    "drives, diagnostics, callbacks", "output (snapshots, progress)"};

static void effect(FILE *f, const char *name, int on, const char *how) {
  fprintf(f, "  %-22s %s%s%s\n", name, on ? "yes" : "no", how && on ? ": " : "",
          how && on ? how : "");
}

void prof_effects(FILE *f, const sim *s) {
  int k, plastic = 0, visc = 0, alpha = 0, friction = s->cfg.mu_default > 0;
  int walls = 0, wallmu = 0, periodic = 0, grav = 0, d;
  char buf[160];
  for (k = 0; k < s->nmat; k++) {
    plastic |= s->mats[k].model == &mat_plastic;
    visc |= s->mats[k].model == &mat_viscoelastic;
    alpha |= s->mats[k].alpha != 0;
  }
  for (k = 0; k < s->nlaw; k++) friction |= s->laws[k].mu > 0;
  for (k = 0; k < NSIDES; k++) {
    walls += s->sides[k].kind == SIDE_WALL;
    wallmu |= s->sides[k].kind == SIDE_WALL && s->sides[k].mu > 0;
    periodic |= s->sides[k].kind == SIDE_PERIODIC;
  }
  for (d = 0; d < DIM; d++) grav |= s->cfg.gravity[d] != 0;
  fprintf(f, "effects:\n");
  snprintf(buf, sizeof buf, "%d fields, %zu shared nodes in the last step",
           s->nfield, s->g.nshared);
  effect(f, "multi-field contact", s->nfield > 1, buf);
  effect(f, "contact friction", s->nfield > 1 && friction, NULL);
  effect(f, "separation check", s->nfield > 1 && s->cfg.gap_check, "reach");
  snprintf(buf, sizeof buf, "%zu interface slots cut so far", s->ncut_total);
  effect(f, "bonds", s->fbond >= 0, buf);
  effect(f, "plasticity", plastic, NULL);
  effect(f, "viscosity", visc, "Maxwell elements");
  effect(f, "temperature", s->ftemp >= 0,
         s->heat ? (alpha ? "computed (heat), thermal strain"
                          : "computed (heat), no alpha")
         : s->temp_on ? (alpha ? "imposed, thermal strain" : "imposed, no alpha")
                      : "field only");
  if (s->heat) {
    const heat_state *h = s->heat;
    snprintf(buf, sizeof buf, "friction split %s, wall friction %g to the "
             "material", h->split == HEAT_SPLIT_EFFUSIVITY ? "by effusivity"
             : "by share", h->wall_share);
    effect(f, "heat", 1, buf);
    snprintf(buf, sizeof buf, "%s contact, %zu substep(s) in the last step",
             h->contact == HEAT_PERFECT ? "perfect" : "conductance", h->nsub);
    effect(f, "conduction", h->conduct, buf);
  } else {
    effect(f, "heat", 0, NULL);
    effect(f, "conduction", 0, NULL);
  }
  snprintf(buf, sizeof buf, "%d", s->ndriven);
  effect(f, "driven bodies", s->ndriven > 0, buf);
  snprintf(buf, sizeof buf, "%d wall sides%s", walls,
           wallmu ? ", with friction" : "");
  effect(f, "walls", walls > 0, buf);
  effect(f, "periodic wrap", periodic, NULL);
  effect(f, "APIC", s->cfg.transfer == TRANSFER_APIC, NULL);
  effect(f, "particle spin", s->cfg.transfer == TRANSFER_SPIN, NULL);
  effect(f, "gravity", grav, NULL);
  fprintf(f, "  %-22s %s, %s, %d particles per cell, flip %g\n", "scheme",
          s->cfg.update == UPDATE_MUSL    ? "MUSL"
          : s->cfg.update == UPDATE_USAVG ? "USAVG"
                                      : "USL",
          shape_names[s->cfg.shape],
          s->cfg.ppc, s->cfg.flip);
  fprintf(f, "  %-22s %d (results do not depend on it)", "threads",
          par_threads(s->work.par));
  if (s->work.bands.plans && par_threads(s->work.par) > 1)
    fprintf(f, "; scatter in parallel passes in %ld of %ld steps",
            s->work.bands.split, s->work.bands.plans);
  fprintf(f, "\n");
}

void prof_report(FILE *f, const sim *s) {
  const sim_prof *p = s->work.prof;
  double total = 0, cpu = 0, crit = 0;
  int k;
  if (!p) return;
  for (k = 0; k < PROF_N; k++) {
    total += p->t[k];
    cpu += p->cpu[k];
    crit += p->crit[k];
  }
  fprintf(f, "time per phase (%ld steps, %.3f s, %.3g ms per step):\n",
          p->steps, total, p->steps ? 1e3 * total / p->steps : 0.0);
  fprintf(f, "  %-32s %9s %7s %9s %9s\n", "", "wall", "share", "CPU",
          "idle cores");
  for (k = 0; k < PROF_N; k++)
    fprintf(f, "  %-32s %9.3f s %6.1f %% %9.3f %9.3f\n", prof_names[k], p->t[k],
            total > 0 ? 100 * p->t[k] / total : 0.0, p->cpu[k], p->crit[k]);
  fprintf(f, "  %-32s %9.3f s %8s %9.3f %9.3f\n", "all", total, "", cpu, crit);
  fprintf(f, "(CPU: the threads' CPU time in the phase; idle cores: the serial "
             "code plus each threaded job's longest part, what the phase "
             "takes with nothing else running)\n");
}
