// chr() takes a UCS-2 code, 0 to 65535. POV-Ray 3.7 stops on line 6:
// "Value -1 cannot be used in chr(...)." (iris gave a blank).
#version 3.7;
#declare Nul = chr(0);
#declare Top = chr(65535);
#declare S = chr(-1);
