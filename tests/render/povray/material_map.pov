#include "stage.inc"
#declare Flat = finish { ambient 0 diffuse 1 }
#declare Red = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { Flat } }
#declare Blue = texture { pigment { rgb <0.2, 0.3, 0.9> } finish { Flat } }
#declare Checks = texture { pigment { checker rgb <0.95, 0.9, 0.8>, rgb <0.1, 0.5, 0.2> scale 0.5 } finish { Flat } }
plane { -z, -0.3 texture { onion texture_map { [0.2 Red] [0.5 Checks] [0.8 Blue] } } }
