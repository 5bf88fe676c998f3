#include <math.h>
#include <stdio.h>
int main(void) {
    char line[4096]; double x;
    while (fgets(line, sizeof line, stdin) && sscanf(line, "[%lf]", &x) == 1) {
        printf("%.17g\n", sqrt(x + 1) - sqrt(x)); fflush(stdout);
    }
}
