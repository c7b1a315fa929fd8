/*
** app.h - the application's entry, one per dimension (main.c is built
** for each; entry.c's main picks).  A command starts in 2-D; when what it
** is given turns out to be 3-D (mvmpm.sim{dim = 3} in the scene, a 3-D
** checkpoint or snapshot) it returns APP_REDO before it has written
** anything, and runs again from the start in 3-D.
*/
#ifndef mvmpm_app_h
#define mvmpm_app_h

/* the exit status that asks for the other dimension */
#define APP_REDO 75

int app_main2(int argc, char **argv);
int app_main3(int argc, char **argv);

/* this file's dimension's entry, for main.c (DIM is dim.h's) */
#define APP_CAT_(a, b) a##b
#define APP_CAT(a, b) APP_CAT_(a, b)
#define app_main APP_CAT(app_main, DIM)

#endif
