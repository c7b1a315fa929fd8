/*
** render_cmd.h - "mvmpm render": a picture of an HDF5 snapshot.
**   mvmpm render SNAPSHOT.h5 [--by KEY] [--out FILE.png] [--width N]
**                [--range LO,HI] [--colormap auto|seq|div]
**                [--title TEXT] [--domain X0,X1,Y0,Y1]
** The snapshot holds no domain, so the window is the particles' extent
** grown by one cell on every side unless --domain gives it.  The default
** output is the snapshot's name with "_KEY.png" for ".h5".
*/
#ifndef mvmpm_render_cmd_h
#define mvmpm_render_cmd_h

/* argv[1] is "render"; returns the exit status (0, 1 failed, 2 usage) */
int render_cmd(int argc, char **argv);

#endif
