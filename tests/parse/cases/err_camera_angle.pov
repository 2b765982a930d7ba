// A negative camera angle: POV-Ray 3.7 stops on line 6, "Negative viewing
// angle." (iris refused 0 too, which POV-Ray takes as no angle: scene
// 251_users_camera_angle0).
#version 3.7;
camera { location -5 * z angle 0 look_at 0 }
camera { location -5 * z angle -10 look_at 0 }
