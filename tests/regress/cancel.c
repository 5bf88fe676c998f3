#include <math.h>
#include <stdio.h>
int main(void) {
    double x;
    while (scanf(" [%lf]", &x) == 1) { printf("%.17g\n", sqrt(x + 1) - sqrt(x)); fflush(stdout); }
}
