#define MVMPM_GIT_VERSION "539e9da-dirty"
#define MVMPM_BUILD "cc (cc (Debian 12.2.0-14+deb12u1) 12.2.0) -std=c11 -pthread -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Wshadow -Wno-unused-parameter -Wno-format-truncation -O3 -march=native -MMD -MP -DDIM=3 -Ibuild3"
