// Front-end benchmark: nested_spheres (see bench/README.md).
// 100 x 1000 = 100,000 spheres from nested loops, each with its own pigment
// whose colour comes from the loop indices. Equivalent to nested_spheres.crt.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.0, 0.0, -10.0> look_at <0.0, 0.0, 0.0> }
light_source { <0.0, 10.0, -10.0> color rgb <1.0, 1.0, 1.0> }

#for (I, 0, 99)
    #for (J, 0, 999)
        sphere {
            <I * 1.0, J * 1.0, 0.0>, 0.4
            pigment { color rgb <I / 100.0, J / 1000.0, 0.5> }
        }
    #end
#end
