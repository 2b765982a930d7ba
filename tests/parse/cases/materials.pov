// Finish and interior keywords, material, the iris IOR extensions and
// light spectra (guarded as scenes guard them for POV-Ray).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 adc_bailout 0.01
  ambient_light rgb 0.5 photons { spacing 0.02 gather 10, 50 autostop 0 }
  radiosity { count 100 } }
background { rgb <0.1, 0.2, 0.3> }
sphere { 0, 1 finish { ambient 0.2 emission 0.5 diffuse albedo 0.7 brilliance 3
  phong 0.5 phong_size 60 specular 0.25 roughness 0.01 metallic
  reflection { 0.1, 0.8 fresnel on falloff 2 exponent 0.9 metallic 0.5 }
  conserve_energy } }
sphere { 0, 1 finish { reflection 0.3 } }
sphere { 0, 1 material { texture { pigment { rgbf <1,1,1,0.9> } }
  interior { ior 1.5 dispersion 1.02 dispersion_samples 20 caustics 0.5
             fade_distance 2 fade_power 1001 fade_color rgb <0.2,0.5,0.8> } }
  hollow photons { target refraction on reflection on collect off } }
#ifdef (iris_version)
sphere { 0, 1 interior { ior 1.5 glass "N-BK7" } }
sphere { 0, 1 interior { sellmeier <1.03961212, 0.231792344, 1.01046945>, <0.00600069867, 0.0200179144, 103.560653> } }
sphere { 0, 1 interior { cauchy 1.5046, 0.0042 } }
sphere { 0, 1 interior { abbe 1.5168, 64.17 } }
sphere { 0, 1 interior { ior_decay 1.6, 1.5, 150 } }
light_source { 0, rgb 1 spectrum "A" }
light_source { 0, rgb 1 blackbody 5000 }
#end
