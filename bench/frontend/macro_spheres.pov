// Front-end benchmark: macro_spheres (see bench/README.md).
// 100,000 calls of a three-parameter macro, each drawing one sphere with its
// own pigment. Equivalent to macro_spheres.crt.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.0, 0.0, -10.0> look_at <0.0, 0.0, 0.0> }
light_source { <0.0, 10.0, -10.0> color rgb <1.0, 1.0, 1.0> }

#macro Ball(X, Y, C)
    sphere { <X, Y, 0.0>, 0.4 pigment { color C } }
#end

#for (I, 0, 99)
    #for (J, 0, 999)
        Ball(I * 1.0, J * 1.0, rgb <I / 100.0, J / 1000.0, 0.5>)
    #end
#end
