#pragma once
// Model texts shared by the model layer's tests: the thesis's Appendix A as printed,
// and a model that uses every statement, option, drive, force, magnitude and shape.

#include <string>

namespace solver::test {

/// seed/thesis.txt, Appendix A, from the first statement to the last, unchanged
/// (blank lines as printed; the Spanish comments in UTF-8).
inline const std::string kAppendixA = R"pad(//Body "A" and "B" GIRO PLUMA

C 1 QI 0.0

B1 0 P1 0.0 0.0 0.0 A1 0.0 0.0 1.0 R1 0.0 1.0 0.0

B2 1 P2 0.0 0.0 -0.21 A2 0.0 0.0 1.0 R2 0.0 1.0 0.0

//Body "B" and "C" LEVANTE PLUMA

C 2 T 1 LL 1.4 UL 1.617 QI 1.464

B1 1 P1 0.0 0.0 0.0 A1 1.0 0.0 0.0 R1 0.0 1.0 0.0

B2 2 P2 0.0 -0.8 0.0 A2 1.0 0.0 0.0 R2 0.0 1.0 0.0

CL1 0.030 0 -.200 CL2 0.030 .650 0

// Body "C" and "D" EXTENSIÓN 1 Y 2

C 3 T 2 LL 0.0 UL 0.900 QI 0.0

B1 2 P1 0.0 0.800 0.0 A1 0.0 0.0 1.0 R1 0.0 1.0 0.0

B2 3 P2 0.0 -0.600 0.0 A2 0.0 0.0 1.0 R2 0.0 1.0 0.0

// Body "E" and "F" GIRO MUÑECA

C 4 LL -1.1344 UL 1.1344 QI 0.0

B1 3 P1 0.0 0.0 0.0 A1 0.0 0.0 1.0 R1 0.0 1.0 0.0

B2 4 P2 0.0 -0.225 0.0 A2 0.0 0.0 1.0 R2 0.0 1.0 0.0

// Body "F" and "G" LEVANTE MUÑECA

C 5 T 1 LL 0.044 UL 0.413 QI 0.412

B1 4 P1 0.0 0.0 -0.3 A1 1.0 0.0 0.0 R1 0.0 1.0 0.0

B2 5 P2 0.0 -0.25 0.0 A2 1.0 0.0 0.0 R2 0.0 1.0 0.0

CL1 0.0 -0.150 -0.450 CL2 0.0 0.0 -0.050

// Body "G" and "H" ROTACIÓN MUÑECA

C 6 QI 0.0

B1 5 P1 0.0 0.0 0.3 A1 0.0 1.0 0.0 R1 0.0 0.0 1.0

B2 6 P2 0.0 -0.25 0.0 A2 0.0 1.0 0.0 R2 0.0 0.0 1.0

// Body "H" and "J" PISTON

C 7 T 2 LL 0.075 UL 0.200 QI 0.075

B1 6 P1 0.0 0.05 0.0 A1 0.0 0.0 1.0 R1 0.0 1.0 0.0

B2 7 P2 0.0 -0.10 0.0 A2 0.0 0.0 1.0 R2 0.0 1.0 0.0

// Body "H" and "K" GARRA SUPERIOR

C 8 T 2 LL -0.150 UL 0.0 QI 0.0

B1 6 P1 0.0 0.05 0.35 A1 0.0 1.0 0.0 R1 0.0 0.0 1.0

B2 8 P2 0.0 -0.10 0.0 A2 0.0 1.0 0.0 R2 0.0 0.0 1.0

// Body "H" and "I" GARRA INFERIOR

C 9 T 2 LL 0.0 UL 0.150 QI 0.0

B1 6 P1 0.0 0.05 -0.35 A1 0.0 1.0 0.0 R1 0.0 0.0 1.0

B2 9 P2 0.0 -0.10 0.0 A2 0.0 1.0 0.0 R2 0.0 0.0 1.0

B 0

B 1

B 2 306.0 73.4487 15.1982 73.4487

B 3 594.0 58.2474 190.9768 58.2474

B 4 200.0 2.07742 3.89517 4,38325

B 5 100.0 0.54153 1.25234 4.11914

B 6 100.0 1.4359 2.65596 0.369125

B 7 10.0 0.0001 0.0001 0.0001

B 8 2.0 0.00001 0.00001 0.00001

B 9 2.0 0.00001 0.00001 0.00001
)pad";

/// Appendix A with its one typo fixed (body 4's "4,38325" read as 4.38325).
inline std::string appendixACorrected()
{
    std::string text = kAppendixA;
    text.replace(text.find("4,38325"), 7, "4.38325");
    return text;
}

/// Every statement, option, kind and shape of the language, with numbers written in
/// every form the lexer reads (.2, -.2, 1e-3, +4.5E2, DEG). It loads without errors
/// when meshes/part.stl exists next to it (otherwise: two mesh-not-found errors).
inline const std::string kEveryStatement = R"pad(// every statement of the model language
GRAVITY 0 -.2 -9.81   # hash comment
RESTITUTION 0.3

B 0 NAME "ground"
B 1
B 2 12.5 0.5 0.4 0.3 CG 0 0.1 -0.05 NAME "arm \"A\" \\ muñeca"
B 3 8 0.2 0.3 0.25 0.01 -0.02 0.005 NAME "tool"
b 4 1e-3 1E-6 1e-6 1e-6 cg .1 .2 .3
B 5 +4.5E2 10 20 15

C 1 NAME "slew"
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 -0.21 A2 0 0 1 R2 0 1 0

C 2 T 1 LL 1.4 UL 1.617 QI 1.464 VI 0.01 NAME "lift"
B1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 2 P2 0 -0.8 0 A2 1 0 0 R2 0 1 0
CL1 0.030 0 -.200 CL2 0.030 .650 0

C 3 T 2 LL 0 UL 0.9 QI 0.3 VI -0.02
B1 2 P1 0 0.8 0 A1 0 0 1 R1 0 1 0
B2 3 P2 0 -0.6 0 A2 0 0 1 R2 0 1 0

c 4 t 0 ll -90 deg ul 90 DEG qi 10 Deg vi 0.5 DEG
b1 3 p1 0 0 0 a1 0 0 1 r1 0 1 0
b2 4 p2 0 -0.225 0 a2 0 0 1 r2 0 1 0

C 5 T 0 LL -1.5 UL 1.5
B2 5 P2 0 0 0 A2 0 1 0 R2 0 0 1   // B2 before B1 is allowed
B1 4 P1 0 0.1 0 A1 0 1 0 R1 0 0 1

D 1 HYD VMAX 0.131 VMIN 0.2 FMAX 54000 FMIN 40000
D 2 HYD PUMP 45 RPM 1480 BORE 0.280 ROD 0.180 PRESSURE 25e6
D 3 PNEU F 2000
D 4 MOTOR T0 300 W0 5
D 5 SERVO KP 1000 KI 10 KD 50 FMAX 800

F 1 POINT B 2 P 0 0.5 0 DIR 0 0 -1 MAG 1000
F 2 POINT B 3 P 0.1 0 0 DIR 1 0 0 MAG SIN 50 0.5 1.5708 LOCAL
F 3 TORQUE B 4 DIR 0 0 1 MAG SIN 5 2 0 1.5
F 4 JOINT 3 MAG TABLE T 0 0 1 100 2.5 -50
F 5 JOINT 1 MAG TABLE Q 3 0 0 0.45 10 0.9 0
F 6 SPRING B1 0 P1 0 2 1 B2 3 P2 0 0 0 K 5000 L0 1.2 C 30
F 7 SPRING B1 1 P1 0 0 0 B2 5 P2 0 0 0 K 0 L0 0
F 8 AERO B 5 P 0 0 0 AREA 0.5 CD 1.1 CL 0.2 RHO 1.2
F 9 AERO B 2 P 0 0 0 AREA 1 CD 0.8
F 10 TORQUE B 5 DIR 0 1 0 MAG -12.5 LOCAL

G 1 B 0 BOX 1.2 1.2 0.08 POS 0 0 -1.04 COLOR 0.4 0.4 0.4
G 2 B 1 CYL 0.32 0.12 POS 0 0 -0.27 AXIS 1 0 0
G 3 B 2 TUBE 0.2 0.15 1.7 RHO 7850
G 4 B 3 SPHERE 0.1 MASS 2.5 COLOR 1 0 0
G 5 B 4 CONE 0.1 0.3 ROT 0 0 1 90
G 6 B 5 ELLIPSOID 0.1 0.2 0.3 ROT 1 1 0 -45 POS 0 0 0.1
G 7 B 2 PRISM 0.05 0 0 0.4 0 0.4 0.2 0 0.3 COLOR 0 0 1
G 8 B 5 MESH "meshes/part.stl" SCALE 0.001 POS 0 0 0 COLOR 0.2 0.2 0.2 MASS 1
G 9 B 3 MESH "meshes/part.stl"
)pad";

}  // namespace solver::test
