#include "stage.inc"
#declare F = function { 0.3 * x * x - 0.2 * y + 0.1 * sin(3 * x * y) }
#declare P = pigment { function { F(x, y, z) } color_map { TwinColors } sine_wave frequency 1.5 }
Wall(P)
