// A parametric's precompute depth must be 1 to 20, as in POV-Ray
// (Precompute_Parametric_Values: "Precompute: invalid depth").
parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1>
  precompute 21 x, y, z }
