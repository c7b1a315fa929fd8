/*
** entry.c - main: the 2-D application first, and the 3-D one when the
** command's scene, checkpoint or snapshot is 3-D (app.h).
*/
#include "app.h"

int main(int argc, char **argv) {
  int rc = app_main2(argc, argv);
  return rc == APP_REDO ? app_main3(argc, argv) : rc;
}
