#include "stage.inc"
#declare Flat = finish { ambient 0 diffuse 1 }
plane { -z, -0.3
    texture { pigment { gradient x color_map { TwinColors } scale 3 } finish { Flat } }
    texture { pigment { checker rgbt <0.1, 0.1, 0.6, 0.5>, rgbt <0, 0, 0, 1> scale 0.5 } finish { Flat } }
}
