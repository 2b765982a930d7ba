// SDL forms POV-Ray 3.7 accepts that iris refused (each was a located
// parse error, so the scene did not render):
// - a declared object or light_source written bare, without object { }:
//   at the top level, as a CSG child and in light_group (Parse_Object's
//   OBJECT_ID_TOKEN case: a copy, no modifiers);
// - union { Id mods } is the copy of Id with the modifiers (Parse_CSG
//   starts with Parse_Object_Id), not a union around the copy;
// - transforms after the objects of clipped_by and of the object
//   pattern move them (Parse_Bound_Clip);
// - a ',' after the last entry of a list pattern, and directives between
//   its entries (Parse_Blend_List; the forms of POV-Ray's Insert Menu).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> right x*4/3 }
#declare Sun = light_source { <4, 8, -6> color rgb 1 }
Sun
#declare Lamp = light_source { <-1, 1.5, -1.5> color rgb <0.6, 0.6, 1> }
#declare Ball = sphere { 0, 0.7 pigment { rgb <1, 0.4, 0.1> } }
#declare Slab = box { <-0.6, -0.2, -0.6>, <0.6, 0.2, 0.6> }
#declare Two = 2;
#declare Floor = plane { y, 0
    pigment { brick color rgb <0.85, 0.1, 0.15>, color rgb <0, 0.6, 0.42>,
              scale 0.08 } }
Floor
// a bare child and a bare light in a union
union { sphere { <-2.2, 0.5, 0>, 0.5 pigment { rgb 0.8 } } Ball Lamp
        translate <-0.4, 0.7, 1> }
// union { Id mods }: Ball itself, its pigment replaced (a union around
// it would leave Ball's own orange)
union { Ball pigment { rgb <0.9, 0.9, 0.2> } scale <1, 0.4, 1>
        translate <1.8, 0.3, -0.5> }
// clipped_by with a transform after the bare identifier
sphere { <0.2, 0.8, -1.2>, 0.8 pigment { rgb <0.3, 0.5, 1> }
         clipped_by { Slab scale <1, 3, 0.8> rotate y*30 translate <0.2, 0.8, -1.2> } }
// the object pattern with transforms after the object; a list pattern
// whose entries have a directive between them and a trailing ','
box { <1.2, 0, 0.8>, <3, 0.05, 2.6>
      pigment { object { Ball scale 1.2 translate <2.1, 0, 1.7>
                         color rgb <0.1, 0.2, 0.1>, color rgb 1, } } }
sphere { <-1.4, 0.45, -1.6>, 0.45
         pigment { checker
                   #if (Two = 2) color rgb <0.9, 0.2, 0.9>, #end
                   color rgb <0.1, 0.8, 0.8>,
                   scale 0.2 } }
light_group { Lamp sphere { <2.6, 0.3, -1.8>, 0.3 pigment { rgb 1 } } }
