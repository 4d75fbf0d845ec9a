#include "stage.inc"
#declare Flat = finish { ambient 0 diffuse 1 }
plane { -z, -0.3 texture { pigment { checker rgb <0.9, 0.8, 0.1>, rgbft <0.2, 0.9, 0.2, 0.5, 0.5> scale 0.5 } finish { Flat } } }
plane { -z, -1 texture { pigment { gradient x color_map { TwinColors } scale 3 } finish { Flat } } }
