<?xml version='1.0' encoding='utf-8'?>
<!DOCTYPE TS>
<TS version="2.1" language="en_US">
<context>
    <name>AttemptLog</name>
    <message>
        <location filename="../trainer/training/attempt_log.cpp" line="+79" />
        <source>the records database is not open: this attempt is kept aside and recorded later</source>
        <translation>the records database is not open: this attempt is kept aside and recorded later</translation>
    </message>
    <message>
        <location line="+47" />
        <source>%1 — this attempt was saved in %2 and will be recorded when the database can be written</source>
        <translation>%1 — this attempt was saved in %2 and will be recorded when the database can be written</translation>
    </message>
    <message>
        <location line="+46" />
        <source>cannot write %1</source>
        <translation>cannot write %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this attempt cannot be kept aside: %1</source>
        <translation>this attempt cannot be kept aside: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 — and the attempt could not be saved aside either: %2</source>
        <translation>%1 — and the attempt could not be saved aside either: %2</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1 is not a pending attempt (%2), and it cannot be moved aside</source>
        <translation>%1 is not a pending attempt (%2), and it cannot be moved aside</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is not a pending attempt (%2): moved to %3</source>
        <translation>%1 is not a pending attempt (%2): moved to %3</translation>
    </message>
    <message>
        <location line="+30" />
        <source>not its format</source>
        <translation>not its format</translation>
    </message>
    <message>
        <location line="+36" />
        <location line="+7" />
        <source>it names no operator</source>
        <translation>it names no operator</translation>
    </message>
</context>
<context>
    <name>CameraPath</name>
    <message>
        <location filename="../trainer/training/camera_path.cpp" line="+46" />
        <source>line %1: %2</source>
        <translation>line %1: %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+15" />
        <source>not a camera path (the first line must be "%1")</source>
        <translation>not a camera path (the first line must be "%1")</translation>
    </message>
    <message>
        <location line="-13" />
        <source>expected 7 numbers (t, target x y z, distance, yaw, pitch), found %1</source>
        <translation>expected 7 numbers (t, target x y z, distance, yaw, pitch), found %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>"%1" is not a number</source>
        <translation>"%1" is not a number</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the time goes back</source>
        <translation>the time goes back</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the distance must be greater than 0</source>
        <translation>the distance must be greater than 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pitch must be within ±π/2</source>
        <translation>the pitch must be within ±π/2</translation>
    </message>
</context>
<context>
    <name>CentreBus</name>
    <message>
        <location filename="../trainer/centre/bus.cpp" line="+172" />
        <source>A %1 message was not sent: its field %2.</source>
        <translation>A %1 message was not sent: its field %2.</translation>
    </message>
    <message>
        <location line="+87" />
        <source>The centre's DDS domain must be a number from 0 to 232 (it is %1).</source>
        <translation>The centre's DDS domain must be a number from 0 to 232 (it is %1).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security needs this node's name (--name), made of letters, digits and - _ . @, not '%1'.</source>
        <translation>DDS Security needs this node's name (--name), made of letters, digits and - _ . @, not '%1'.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security covers the domains 0 to 230: choose one of them for the centre (it is %1).</source>
        <translation>DDS Security covers the domains 0 to 230: choose one of them for the centre (it is %1).</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Could not join the centre's network (DDS domain %1): %2. Check the centre's network interfaces and peers.</source>
        <translation>Could not join the centre's network (DDS domain %1): %2. Check the centre's network interfaces and peers.</translation>
    </message>
    <message>
        <location line="+19" />
        <source>DDS Security refused node %1's identity or permissions in %2 (%3). Check that the node's files and the centre's identity_ca.pem, permissions_ca.pem and governance.p7s come from the same 'padrob centre pki', and that the security plugins of Cyclone DDS are installed.</source>
        <translation>DDS Security refused node %1's identity or permissions in %2 (%3). Check that the node's files and the centre's identity_ca.pem, permissions_ca.pem and governance.p7s come from the same 'padrob centre pki', and that the security plugins of Cyclone DDS are installed.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Could not join the centre's network (DDS domain %1): %2.</source>
        <translation>Could not join the centre's network (DDS domain %1): %2.</translation>
    </message>
    <message>
        <location line="+35" />
        <location line="+12" />
        <source>Could not create the centre's topic %1: %2.</source>
        <translation>Could not create the centre's topic %1: %2.</translation>
    </message>
</context>
<context>
    <name>CentreKey</name>
    <message>
        <location filename="../trainer/centre/signing.cpp" line="+192" />
        <source>Cannot read the centre's key file %1: %2.</source>
        <translation>Cannot read the centre's key file %1: %2.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The centre's key file %1 can be read by other users: make it readable by its owner only (chmod 600 %1).</source>
        <translation>The centre's key file %1 can be read by other users: make it readable by its owner only (chmod 600 %1).</translation>
    </message>
    <message>
        <location line="+15" />
        <source>The node key file %1 must name its node on its first line ('%2 NAME', a name of at most %3 bytes without spaces); make one with 'padrob centre key --key CENTRE-KEY --node NAME FILE'.</source>
        <translation>The node key file %1 must name its node on its first line ('%2 NAME', a name of at most %3 bytes without spaces); make one with 'padrob centre key --key CENTRE-KEY --node NAME FILE'.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>The centre's key file %1 must hold 64 hexadecimal digits (32 bytes); make one with 'padrob centre key FILE'.</source>
        <translation>The centre's key file %1 must hold 64 hexadecimal digits (32 bytes); make one with 'padrob centre key FILE'.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1 exists already: a centre's key is never overwritten.</source>
        <translation>%1 exists already: a centre's key is never overwritten.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Cannot write the centre's key file %1: %2.</source>
        <translation>Cannot write the centre's key file %1: %2.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>A node's key is made from the centre's key, not from another node's key.</source>
        <translation>A node's key is made from the centre's key, not from another node's key.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A node's name has 1 to %1 bytes and no spaces.</source>
        <translation>A node's name has 1 to %1 bytes and no spaces.</translation>
    </message>
    <message>
        <location line="+63" />
        <source>%1 is node %2's key, not %3's: give %3 its own (padrob centre key --key CENTRE-KEY --node %3 FILE) or the centre's key.</source>
        <translation>%1 is node %2's key, not %3's: give %3 its own (padrob centre key --key CENTRE-KEY --node %3 FILE) or the centre's key.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 is node %2's key: an instructor needs the centre's key, which signs the commands for every station and checks what each says.</source>
        <translation>%1 is node %2's key: an instructor needs the centre's key, which signs the commands for every station and checks what each says.</translation>
    </message>
</context>
<context>
    <name>CentrePki</name>
    <message>
        <location filename="../trainer/centre/pki.cpp" line="+51" />
        <source>%1 exists already: a PKI file is never replaced (remove it first if you mean to).</source>
        <translation>%1 exists already: a PKI file is never replaced (remove it first if you mean to).</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Could not write %1: %2.</source>
        <translation>Could not write %1: %2.</translation>
    </message>
    <message>
        <location line="+160" />
        <source>OpenSSL could not make %1.</source>
        <translation>OpenSSL could not make %1.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1 holds a centre's PKI already: it is never replaced.</source>
        <translation>%1 holds a centre's PKI already: it is never replaced.</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+48" />
        <source>Could not make the folder %1.</source>
        <translation>Could not make the folder %1.</translation>
    </message>
    <message>
        <location line="-43" />
        <source>the CAs' keys</source>
        <translation>the CAs' keys</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the CAs' certificates</source>
        <translation>the CAs' certificates</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the signed governance document</source>
        <translation>the signed governance document</translation>
    </message>
    <message>
        <location line="+14" />
        <source>'%1' cannot be a node's name in the centre's PKI: use letters, digits and - _ . @ (up to 64).</source>
        <translation>'%1' cannot be a node's name in the centre's PKI: use letters, digits and - _ . @ (up to 64).</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 has no centre PKI (identity_ca.pem/.key, permissions_ca.pem/.key): make it with 'padrob centre pki %1'.</source>
        <translation>%1 has no centre PKI (identity_ca.pem/.key, permissions_ca.pem/.key): make it with 'padrob centre pki %1'.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Node %1 has an identity already in %2: it is never replaced.</source>
        <translation>Node %1 has an identity already in %2: it is never replaced.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>the node's certificate</source>
        <translation>the node's certificate</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the signed permissions document</source>
        <translation>the signed permissions document</translation>
    </message>
    <message>
        <location line="+18" />
        <source>DDS Security: %1 is missing. Issue this node's identity with 'padrob centre pki %2 --node %3' on the computer that holds the centre's PKI, and copy the files here.</source>
        <translation>DDS Security: %1 is missing. Issue this node's identity with 'padrob centre pki %2 --node %3' on the computer that holds the centre's PKI, and copy the files here.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>DDS Security: %1 is not a certificate. Copy the centre's identity_ca.pem again.</source>
        <translation>DDS Security: %1 is not a certificate. Copy the centre's identity_ca.pem again.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>DDS Security: %1 is not a certificate. Issue this node's identity again with 'padrob centre pki %2 --node %3'.</source>
        <translation>DDS Security: %1 is not a certificate. Issue this node's identity again with 'padrob centre pki %2 --node %3'.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>DDS Security: %1 was not issued by this centre's identity CA (%2). Issue this node's identity with 'padrob centre pki DIR --node %3' using the centre's PKI.</source>
        <translation>DDS Security: %1 was not issued by this centre's identity CA (%2). Issue this node's identity with 'padrob centre pki DIR --node %3' using the centre's PKI.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>DDS Security: %1 is not valid now (expired, or this computer's clock is wrong). Check the clock, or issue a new identity for the node.</source>
        <translation>DDS Security: %1 is not valid now (expired, or this computer's clock is wrong). Check the clock, or issue a new identity for the node.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>DDS Security: %1 is not the private key of %2. Copy the node's folder again.</source>
        <translation>DDS Security: %1 is not the private key of %2. Copy the node's folder again.</translation>
    </message>
</context>
<context>
    <name>Diagnostics</name>
    <message>
        <location filename="../ide/studio/editor/diagnostic_text.cpp" line="+23" />
        <location line="+4" />
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location line="-3" />
        <source>Warning</source>
        <translation>Warning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Note</source>
        <translation>Note</translation>
    </message>
    <message>
        <location line="+76" />
        <source>Hint:</source>
        <translation>Hint:</translation>
    </message>
    <message>
        <location filename="../ide/i18n/diagnostic_text.cpp" line="+31" />
        <location line="+4" />
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <location line="-3" />
        <source>warning</source>
        <translation>warning</translation>
    </message>
    <message>
        <location line="+1" />
        <source>note</source>
        <translation>note</translation>
    </message>
    <message>
        <location filename="../solver/core/diagnostic.cpp" line="+131" />
        <source>too many problems; the rest are not listed</source>
        <translation>too many problems; the rest are not listed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the ones above first</source>
        <translation>fix the ones above first</translation>
    </message>
    <message>
        <location filename="../solver/inertia/solid_inertia.cpp" line="+68" />
        <location line="+131" />
        <location filename="../solver/parse/parser.cpp" line="+1412" />
        <location filename="../solver/spec/validate.cpp" line="+510" />
        <location line="+107" />
        <source>graphic %1</source>
        <translation>graphic %1</translation>
    </message>
    <message>
        <location line="-125" />
        <location filename="../solver/spec/validate.cpp" line="-53" />
        <source>%1: mesh file '%2' not found (looked for %3)</source>
        <translation>%1: mesh file '%2' not found (looked for %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../solver/spec/validate.cpp" line="+4" />
        <source>mesh paths are relative to the model file's folder</source>
        <translation>mesh paths are relative to the model file's folder</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: mesh file '%2' cannot be read: %3</source>
        <translation>%1: mesh file '%2' cannot be read: %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>export the mesh again (STL, OBJ, PLY, …) or check that the file is not damaged</source>
        <translation>export the mesh again (STL, OBJ, PLY, …) or check that the file is not damaged</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the mesh is not closed: %2 open edges</source>
        <translation>%1: the mesh is not closed: %2 open edges</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a solid's surface must be watertight (every edge joins two triangles); close its holes in a mesh editor</source>
        <translation>a solid's surface must be watertight (every edge joins two triangles); close its holes in a mesh editor</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the mesh's faces are not consistently oriented: %2 edges</source>
        <translation>%1: the mesh's faces are not consistently oriented: %2 edges</translation>
    </message>
    <message>
        <location line="+3" />
        <source>recalculate the normals in a mesh editor so they all point outwards</source>
        <translation>recalculate the normals in a mesh editor so they all point outwards</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1: the mesh encloses no volume</source>
        <translation>%1: the mesh encloses no volume</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a solid needs a closed surface around a volume</source>
        <translation>a solid needs a closed surface around a volume</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: the mesh's normals point inwards (negative volume); its absolute value is used</source>
        <translation>%1: the mesh's normals point inwards (negative volume); its absolute value is used</translation>
    </message>
    <message>
        <location line="+2" />
        <source>flip the normals in a mesh editor</source>
        <translation>flip the normals in a mesh editor</translation>
    </message>
    <message>
        <location line="+78" />
        <source>%1: MASS is negative</source>
        <translation>%1: MASS is negative</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/spec/validate.cpp" line="+19" />
        <source>a mass is ≥ 0, in kg</source>
        <translation>a mass is ≥ 0, in kg</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: RHO must be positive</source>
        <translation>%1: RHO must be positive</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/spec/validate.cpp" line="+4" />
        <source>a density in kg/m³ (steel: 7850)</source>
        <translation>a density in kg/m³ (steel: 7850)</translation>
    </message>
    <message>
        <location filename="../solver/collision/collision_world.cpp" line="+114" />
        <source>G %1 is left out of the clearance checks: %2</source>
        <translation>G %1 is left out of the clearance checks: %2</translation>
    </message>
    <message>
        <location filename="../solver/compile/compile.cpp" line="+228" />
        <location filename="../solver/compile/initial_configuration.cpp" line="+44" />
        <location line="+9" />
        <location filename="../solver/compile/topology.cpp" line="+39" />
        <location filename="../solver/parse/parser.cpp" line="-551" />
        <location line="+135" />
        <location filename="../solver/spec/validate.cpp" line="-558" />
        <location line="+582" />
        <source>joint %1</source>
        <translation>joint %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the drive on %1 cannot act: the joint closes a loop, so it is a constraint, not a coordinate</source>
        <translation>the drive on %1 cannot act: the joint closes a loop, so it is a constraint, not a coordinate</translation>
    </message>
    <message>
        <location line="+2" />
        <source>move the drive to another joint of the loop, or leave one joint of the loop passive</source>
        <translation>move the drive to another joint of the loop, or leave one joint of the loop passive</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 closes a loop: its limits LL/UL are not enforced</source>
        <translation>%1 closes a loop: its limits LL/UL are not enforced</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put the limits on another joint of the loop (a tree joint)</source>
        <translation>put the limits on another joint of the loop (a tree joint)</translation>
    </message>
    <message>
        <location filename="../solver/compile/initial_configuration.cpp" line="+3" />
        <source>joints %1 and %2</source>
        <translation>joints %1 and %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../solver/compile/topology.cpp" line="-14" />
        <location filename="../solver/integrate/simulation.cpp" line="+55" />
        <location filename="../solver/parse/parser.cpp" line="-200" />
        <location filename="../solver/spec/validate.cpp" line="-589" />
        <location line="+588" />
        <source>body %1</source>
        <translation>body %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 is not connected to ground: no chain of joints leads from body 0 to it</source>
        <translation>%1 is not connected to ground: no chain of joints leads from body 0 to it</translation>
    </message>
    <message>
        <location line="+2" />
        <source>add a joint (C) that connects it to ground or to a connected body</source>
        <translation>add a joint (C) that connects it to ground or to a connected body</translation>
    </message>
    <message>
        <location line="+24" />
        <source>%1 is a free joint (T 3), but its body B2 is also held by other joints (a closed loop)</source>
        <translation>%1 is a free joint (T 3), but its body B2 is also held by other joints (a closed loop)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a free body moves only through its free joint: remove the other joints between it and the rest, or use T 0, T 1 or T 2</source>
        <translation>a free body moves only through its free joint: remove the other joints between it and the rest, or use T 0, T 1 or T 2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 is a free joint (T 3) whose B2 is nearer the ground than its B1</source>
        <translation>%1 is a free joint (T 3) whose B2 is nearer the ground than its B1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write the free joint from the side nearer the ground (B1, usually body 0) to the free body (B2)</source>
        <translation>write the free joint from the side nearer the ground (B1, usually body 0) to the free body (B2)</translation>
    </message>
    <message>
        <location filename="../solver/compile/initial_configuration.cpp" line="+17" />
        <source>joint %1's actuator</source>
        <translation>joint %1's actuator</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 keeps the same length %2 m whatever the joint angle: CL1 or CL2 lies on the joint axis A, so the actuator cannot turn the joint</source>
        <translation>%1 keeps the same length %2 m whatever the joint angle: CL1 or CL2 lies on the joint axis A, so the actuator cannot turn the joint</translation>
    </message>
    <message>
        <location line="+4" />
        <source>place CL1 (on body %1) and CL2 (on body %2) away from the joint axis, so that the actuator length changes as the joint turns</source>
        <translation>place CL1 (on body %1) and CL2 (on body %2) away from the joint axis, so that the actuator length changes as the joint turns</translation>
    </message>
    <message>
        <location line="+21" />
        <source>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2 (a reachable QI is taken at the joint angle nearest to 0)</source>
        <translation>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2 (a reachable QI is taken at the joint angle nearest to 0)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2</source>
        <translation>the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint turns; choose %3 within that range, or check CL1, CL2 and the joint points P1, P2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 = %2 m is beyond the reach of %3 (%4 m .. %5 m)</source>
        <translation>%1 = %2 m is beyond the reach of %3 (%4 m .. %5 m)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>longest</source>
        <translation>longest</translation>
    </message>
    <message>
        <location line="+1" />
        <source>shortest</source>
        <translation>shortest</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, and no %5 stops it before</source>
        <translation>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, and no %5 stops it before</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, between LL and UL</source>
        <translation>%1 reaches a dead point inside its stroke: its length is %2 (%3 m) at joint angle %4 rad, between LL and UL</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 below %2 m</source>
        <translation>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 below %2 m</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 above %2 m</source>
        <translation>the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set %1 above %2 m</translation>
    </message>
    <message>
        <location line="+104" />
        <source>P2 lies %1 m off the sliding line through P1</source>
        <translation>P2 lies %1 m off the sliding line through P1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>P1 and P2 stay %1 m apart</source>
        <translation>P1 and P2 stay %1 m apart</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the joint frames are turned by about %1 rad</source>
        <translation>the joint frames are turned by about %1 rad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the axes A1 and A2 are %1 rad out of line</source>
        <translation>the axes A1 and A2 are %1 rad out of line</translation>
    </message>
    <message>
        <location line="+12" />
        <source>check the joint points P1, P2 and the link lengths of the loop</source>
        <translation>check the joint points P1, P2 and the link lengths of the loop</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the joint points P1, P2 and the link lengths of the loop, and the QI of its independent coordinates (%1)</source>
        <translation>check the joint points P1, P2 and the link lengths of the loop, and the QI of its independent coordinates (%1)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2</source>
        <translation>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2 (%3)</source>
        <translation>the loop closed by %1 cannot be assembled at the initial configuration: its closure equations keep a residual of %2 (%3)</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+249" />
        <source>give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint</source>
        <translation>give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint</translation>
    </message>
    <message>
        <location line="-228" />
        <source>the bodies it moves have no mass</source>
        <translation>the bodies it moves have no mass</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+225" />
        <source>the bodies it moves have no mass, or only mass on its axis and no inertia about it</source>
        <translation>the bodies it moves have no mass, or only mass on its axis and no inertia about it</translation>
    </message>
    <message>
        <location line="-222" />
        <location line="+219" />
        <source>%1 moves no mass: %2, so the mass matrix is singular at the initial configuration</source>
        <translation>%1 moves no mass: %2, so the mass matrix is singular at the initial configuration</translation>
    </message>
    <message>
        <location line="-215" />
        <source>%1 and the loop it drives (%2) move no mass: %3, so the mass matrix is singular at the initial configuration</source>
        <translation>%1 and the loop it drives (%2) move no mass: %3, so the mass matrix is singular at the initial configuration</translation>
    </message>
    <message>
        <location line="+31" />
        <source>%1 for joint %2</source>
        <translation>%1 for joint %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 together move no mass: the motion with rates %2 leaves every body with mass at rest, so the mass matrix is singular at the initial configuration</source>
        <translation>%1 together move no mass: the motion with rates %2 leaves every body with mass at rest, so the mass matrix is singular at the initial configuration</translation>
    </message>
    <message>
        <location filename="../solver/core/text_file.cpp" line="+20" />
        <source>give the path of a %1 file</source>
        <translation>give the path of a %1 file</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../solver/inertia/triangle_mesh.cpp" line="+88" />
        <source>no such file</source>
        <translation>no such file</translation>
    </message>
    <message>
        <location line="+0" />
        <source>check the path</source>
        <translation>check the path</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this is a folder, not %1</source>
        <translation>this is a folder, not %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>this is not a regular file</source>
        <translation>this is not a regular file</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file is too large for %1 (%2 MB; the limit is %3 MB)</source>
        <translation>the file is too large for %1 (%2 MB; the limit is %3 MB)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>cannot be read (permission denied?)</source>
        <translation>cannot be read (permission denied?)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the file's permissions</source>
        <translation>check the file's permissions</translation>
    </message>
    <message>
        <location line="+11" />
        <source>reading failed</source>
        <translation>reading failed</translation>
    </message>
    <message>
        <location line="+0" />
        <source>check the disk and the file's permissions</source>
        <translation>check the disk and the file's permissions</translation>
    </message>
    <message>
        <location filename="../solver/inertia/triangle_mesh.cpp" line="+6" />
        <source>the file holds no scene</source>
        <translation>the file holds no scene</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file holds no triangles</source>
        <translation>the file holds no triangles</translation>
    </message>
    <message>
        <location filename="../solver/io/input_table.cpp" line="+144" />
        <source>%1: the value has no closing quote</source>
        <translation>%1: the value has no closing quote</translation>
    </message>
    <message>
        <location line="+1" />
        <source>close the quote, or write the number without quotes</source>
        <translation>close the quote, or write the number without quotes</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: no value</source>
        <translation>%1: no value</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number (0 for a closed valve)</source>
        <translation>write a number (0 for a closed valve)</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+16" />
        <location filename="../solver/parse/parser.cpp" line="-536" />
        <location line="+9" />
        <source>%1: '%2' is not a number</source>
        <translation>%1: '%2' is not a number</translation>
    </message>
    <message>
        <location line="-15" />
        <location filename="../solver/parse/parser.cpp" line="-8" />
        <source>use '.' as the decimal separator: %1</source>
        <translation>use '.' as the decimal separator: %1</translation>
    </message>
    <message>
        <location line="+5" />
        <location filename="../solver/parse/parser.cpp" line="+2" />
        <source>%1: '%2' is not a finite number</source>
        <translation>%1: '%2' is not a finite number</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../solver/parse/parser.cpp" line="+1" />
        <source>write a finite value; NaN and infinity are not allowed</source>
        <translation>write a finite value; NaN and infinity are not allowed</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: '%2' is too large</source>
        <translation>%1: '%2' is too large</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a value that fits a double (below 1.8e308)</source>
        <translation>write a value that fits a double (below 1.8e308)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>write a number in the C locale: '.' as the decimal point, e.g. -0.25 or 1e-3</source>
        <translation>write a number in the C locale: '.' as the decimal point, e.g. -0.25 or 1e-3</translation>
    </message>
    <message>
        <location line="+66" />
        <source>the input file is empty</source>
        <translation>the input file is empty</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a header naming the columns, then one row per time, e.g. t,u2 then 0,0.5</source>
        <translation>write a header naming the columns, then one row per time, e.g. t,u2 then 0,0.5</translation>
    </message>
    <message>
        <location line="+22" />
        <source>the column name has no closing quote</source>
        <translation>the column name has no closing quote</translation>
    </message>
    <message>
        <location line="+1" />
        <source>close the quote, or write the name without quotes</source>
        <translation>close the quote, or write the name without quotes</translation>
    </message>
    <message>
        <location line="+5" />
        <source>column %1 has no name</source>
        <translation>column %1 has no name</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name every column: t for the time, u&lt;joint id&gt; for a command (e.g. u2)</source>
        <translation>name every column: t for the time, u&lt;joint id&gt; for a command (e.g. u2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>column 't' appears twice (first at column %1)</source>
        <translation>column 't' appears twice (first at column %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+16" />
        <source>remove one of them</source>
        <translation>remove one of them</translation>
    </message>
    <message>
        <location line="-5" />
        <source>column '%1' is joint %2's command again ('%3' at column %4)</source>
        <translation>column '%1' is joint %2's command again ('%3' at column %4)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>'%1' is not an input column name</source>
        <translation>'%1' is not an input column name</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name the time column t and each command column u&lt;joint id&gt;, e.g. u2</source>
        <translation>name the time column t and each command column u&lt;joint id&gt;, e.g. u2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the header has no 't' column</source>
        <translation>the header has no 't' column</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the first line names the columns: t, then u&lt;joint id&gt; for each command, e.g. t,u2</source>
        <translation>the first line names the columns: t, then u&lt;joint id&gt; for each command, e.g. t,u2</translation>
    </message>
    <message>
        <location line="+19" />
        <source>this row has %1 value; the header names %2 columns</source>
        <translation>this row has %1 value; the header names %2 columns</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+7" />
        <source>this row has %1 values; the header names %2 columns</source>
        <translation>this row has %1 values; the header names %2 columns</translation>
    </message>
    <message>
        <location line="-4" />
        <source>give a value for every column (0 for a closed valve)</source>
        <translation>give a value for every column (0 for a closed valve)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this row has %1 values; the header names %2 column</source>
        <translation>this row has %1 values; the header names %2 column</translation>
    </message>
    <message>
        <location line="+5" />
        <source>one value per column; if ',' is a decimal separator here, write '.' instead (0.5, not 0,5)</source>
        <translation>one value per column; if ',' is a decimal separator here, write '.' instead (0.5, not 0,5)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>one value per column, separated by %1</source>
        <translation>one value per column, separated by %1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>time</source>
        <translation>time</translation>
    </message>
    <message>
        <location line="+1" />
        <source>column '%1'</source>
        <translation>column '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>column %1</source>
        <translation>column %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>time %1 repeats the time of line %2</source>
        <translation>time %1 repeats the time of line %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>time %1 comes after time %2 (line %3); times must increase</source>
        <translation>time %1 comes after time %2 (line %3); times must increase</translation>
    </message>
    <message>
        <location line="+5" />
        <source>sort the rows by time, each time once</source>
        <translation>sort the rows by time, each time once</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: %2 is outside [-1, 1]</source>
        <translation>%1: %2 is outside [-1, 1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a command is a valve spool position (or joystick axis) from -1 to 1</source>
        <translation>a command is a valve spool position (or joystick axis) from -1 to 1</translation>
    </message>
    <message>
        <location line="+20" />
        <source>the input file has a header but no rows</source>
        <translation>the input file has a header but no rows</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add one row per time under the header, e.g. 0,0.5</source>
        <translation>add one row per time under the header, e.g. 0,0.5</translation>
    </message>
    <message>
        <location line="+11" />
        <source>an input file</source>
        <translation>an input file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>split the session, or record the commands less often</source>
        <translation>split the session, or record the commands less often</translation>
    </message>
    <message>
        <location line="+60" />
        <source>column '%1': the model has no joint %2</source>
        <translation>column '%1': the model has no joint %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the model has no drives; remove the column</source>
        <translation>the model has no drives; remove the column</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the joints with a drive are %1</source>
        <translation>the joints with a drive are %1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>column '%1': joint %2 has no drive</source>
        <translation>column '%1': joint %2 has no drive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a command moves a drive: remove the column, or give the joint a drive (D %1 …)</source>
        <translation>a command moves a drive: remove the column, or give the joint a drive (D %1 …)</translation>
    </message>
    <message>
        <location line="+17" />
        <source>no column for joint %1's drive</source>
        <translation>no column for joint %1's drive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no columns for the drives of joints %1</source>
        <translation>no columns for the drives of joints %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the table has one column u&lt;joint id&gt; per drive; write 0 in a column to keep that valve closed</source>
        <translation>the table has one column u&lt;joint id&gt; per drive; write 0 in a column to keep that valve closed</translation>
    </message>
    <message>
        <location filename="../solver/pipeline.cpp" line="+94" />
        <source>this is not a text file (it contains a NUL byte here)</source>
        <translation>this is not a text file (it contains a NUL byte here)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+10" />
        <source>a model is a text file (.pad); open the model, not a mesh, image or archive</source>
        <translation>a model is a text file (.pad); open the model, not a mesh, image or archive</translation>
    </message>
    <message>
        <location line="-3" />
        <source>this is not a text file (%1 control characters in its first %2 bytes)</source>
        <translation>this is not a text file (%1 control characters in its first %2 bytes)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>the file is not UTF-8 (byte 0x%1 here); it was read as Latin-1 (ISO 8859-1)</source>
        <translation>the file is not UTF-8 (byte 0x%1 here); it was read as Latin-1 (ISO 8859-1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>save the file as UTF-8 so every editor shows its accents the same way</source>
        <translation>save the file as UTF-8 so every editor shows its accents the same way</translation>
    </message>
    <message>
        <location line="+65" />
        <source>a model file</source>
        <translation>a model file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a model is a short text; put meshes in their own files (G … MESH "file")</source>
        <translation>a model is a short text; put meshes in their own files (G … MESH "file")</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="-587" />
        <source>body %1 (%2)</source>
        <translation>body %1 (%2)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>joint %1 (%2)</source>
        <translation>joint %1 (%2)</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="+761" />
        <location filename="../solver/spec/validate.cpp" line="+5" />
        <source>drive on joint %1</source>
        <translation>drive on joint %1</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="+16" />
        <source>%1 is defined twice (first at line %2)</source>
        <translation>%1 is defined twice (first at line %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give it another id or remove one of the two</source>
        <translation>give it another id or remove one of the two</translation>
    </message>
    <message>
        <location line="+17" />
        <source>body 0 is the ground and cannot have a mass or inertia</source>
        <translation>body 0 is the ground and cannot have a mass or inertia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove the numbers from 'B 0', or give the body another id</source>
        <translation>remove the numbers from 'B 0', or give the body another id</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 has a negative mass (%2 kg)</source>
        <translation>%1 has a negative mass (%2 kg)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a mass is zero or positive, in kg</source>
        <translation>a mass is zero or positive, in kg</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1's mass %2 kg is beyond any machine's (at most %3 kg)</source>
        <translation>%1's mass %2 kg is beyond any machine's (at most %3 kg)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>check the units: a mass is in kg</source>
        <translation>check the units: a mass is in kg</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1's inertia %2 kg m² is beyond any machine's (at most %3 kg m²)</source>
        <translation>%1's inertia %2 kg m² is beyond any machine's (at most %3 kg m²)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>check the units: moments and products of inertia are in kg m²</source>
        <translation>check the units: moments and products of inertia are in kg m²</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1's inertia tensor is not positive semi-definite (principal moments %2, %3, %4 kg m²)</source>
        <translation>%1's inertia tensor is not positive semi-definite (principal moments %2, %3, %4 kg m²)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>moments of inertia are zero or positive, and products of inertia cannot outweigh them; check signs and units (kg m²)</source>
        <translation>moments of inertia are zero or positive, and products of inertia cannot outweigh them; check signs and units (kg m²)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1's principal moments of inertia %2, %3, %4 kg m² break the triangle inequality (%2 + %3 &lt; %4): no real body has them</source>
        <translation>%1's principal moments of inertia %2, %3, %4 kg m² break the triangle inequality (%2 + %3 &lt; %4): no real body has them</translation>
    </message>
    <message>
        <location line="+6" />
        <source>check the values; the inertia calculator computes them from the body's shapes</source>
        <translation>check the values; the inertia calculator computes them from the body's shapes</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 has no mass but a non-zero inertia</source>
        <translation>%1 has no mass but a non-zero inertia</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give its mass, or set the inertia to zero as well</source>
        <translation>give its mass, or set the inertia to zero as well</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+5" />
        <location line="+337" />
        <location line="+84" />
        <source>%1: %2 has zero length</source>
        <translation>%1: %2 has zero length</translation>
    </message>
    <message>
        <location line="-425" />
        <source>the axis is a direction, e.g. A%1 0 0 1</source>
        <translation>the axis is a direction, e.g. A%1 0 0 1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the reference direction is a direction perpendicular to A%1, e.g. R%1 0 1 0</source>
        <translation>the reference direction is a direction perpendicular to A%1, e.g. R%1 0 1 0</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: R%2 is parallel to A%2</source>
        <translation>%1: R%2 is parallel to A%2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>R%1 must be perpendicular to the axis A%1</source>
        <translation>R%1 must be perpendicular to the axis A%1</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: R%2 is not perpendicular to A%2 (angle %3°); R%2 is made perpendicular</source>
        <translation>%1: R%2 is not perpendicular to A%2 (angle %3°); R%2 is made perpendicular</translation>
    </message>
    <message>
        <location line="+4" />
        <source>write R%1 at 90° to A%1</source>
        <translation>write R%1 at 90° to A%1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>joint %1 is a free joint (T 3): %2 does not apply to it</source>
        <translation>joint %1 is a free joint (T 3): %2 does not apply to it</translation>
    </message>
    <message>
        <location line="+3" />
        <source>remove %1; place the free body with the joint's P1, A1 and R1 (it starts where its two joint frames coincide, at rest)</source>
        <translation>remove %1; place the free body with the joint's P1, A1 and R1 (it starts where its two joint frames coincide, at rest)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>joint %1 is a free joint (T 3) whose B2 is the ground</source>
        <translation>joint %1 is a free joint (T 3) whose B2 is the ground</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the free body is B2: write B1 0 … and B2 with the body that moves</source>
        <translation>the free body is B2: write B1 0 … and B2 with the body that moves</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 has no B%2 line</source>
        <translation>%1 has no B%2 line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>follow the C line with B%1 body P%1 x y z A%1 x y z R%1 x y z</source>
        <translation>follow the C line with B%1 body P%1 x y z A%1 x y z R%1 x y z</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: body %2 (B%3) is not defined</source>
        <translation>%1: body %2 (B%3) is not defined</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add 'B %1 m Ixx Iyy Izz', or use an existing body</source>
        <translation>add 'B %1 m Ixx Iyy Izz', or use an existing body</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 connects body %2 to itself</source>
        <translation>%1 connects body %2 to itself</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+262" />
        <source>B1 and B2 must name two different bodies</source>
        <translation>B1 and B2 must name two different bodies</translation>
    </message>
    <message>
        <location line="-255" />
        <source>%1 is a pivoted linear actuator (T 1) but has no CL1/CL2 line</source>
        <translation>%1 is a pivoted linear actuator (T 1) but has no CL1/CL2 line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 is a pivoted linear actuator (T 1) but has no %2</source>
        <translation>%1 is a pivoted linear actuator (T 1) but has no %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in their local frames</source>
        <translation>add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in their local frames</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 has CL1/CL2 but is not a pivoted linear actuator</source>
        <translation>%1 has CL1/CL2 but is not a pivoted linear actuator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line</source>
        <translation>CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1: %2 = %3 is beyond any machine's (at most %4 in size)</source>
        <translation>%1: %2 = %3 is beyond any machine's (at most %4 in size)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>check the units: lengths in m, angles in rad, rates in m/s or rad/s</source>
        <translation>check the units: lengths in m, angles in rad, rates in m/s or rad/s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the lower limit LL = %2 is above the upper limit UL = %3</source>
        <translation>%1: the lower limit LL = %2 is above the upper limit UL = %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>swap LL and UL</source>
        <translation>swap LL and UL</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+9" />
        <source>%1: %2 = %3 m, but a T 1 joint's coordinate is the actuator's length</source>
        <translation>%1: %2 = %3 m, but a T 1 joint's coordinate is the actuator's length</translation>
    </message>
    <message>
        <location line="-5" />
        <source>give the cylinder's length between CL1 and CL2, in metres (positive)</source>
        <translation>give the cylinder's length between CL1 and CL2, in metres (positive)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>give the cylinder's initial length between CL1 and CL2, in metres (positive)</source>
        <translation>give the cylinder's initial length between CL1 and CL2, in metres (positive)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: QI = %2 is below the lower limit LL = %3</source>
        <translation>%1: QI = %2 is below the lower limit LL = %3</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+7" />
        <source>give QI between LL and UL</source>
        <translation>give QI between LL and UL</translation>
    </message>
    <message>
        <location line="-4" />
        <source>%1: QI = %2 is above the upper limit UL = %3</source>
        <translation>%1: QI = %2 is above the upper limit UL = %3</translation>
    </message>
    <message>
        <location line="+12" />
        <source>%1: VI = %2 moves the joint past its upper limit UL = %3, where it starts</source>
        <translation>%1: VI = %2 moves the joint past its upper limit UL = %3, where it starts</translation>
    </message>
    <message>
        <location line="+4" />
        <source>start it inside its limits, or give VI ≤ 0</source>
        <translation>start it inside its limits, or give VI ≤ 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: VI = %2 moves the joint past its lower limit LL = %3, where it starts</source>
        <translation>%1: VI = %2 moves the joint past its lower limit LL = %3, where it starts</translation>
    </message>
    <message>
        <location line="+4" />
        <source>start it inside its limits, or give VI ≥ 0</source>
        <translation>start it inside its limits, or give VI ≥ 0</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: a CYL drive needs a T 1 or T 2 joint, but %2 is revolute</source>
        <translation>%1: a CYL drive needs a T 1 or T 2 joint, but %2 is revolute</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive a revolute joint with D j HMOTOR PUMP id DISP Dm VALVE Qn DP dp, or make the joint T 1 (a pivoted cylinder) or T 2</source>
        <translation>drive a revolute joint with D j HMOTOR PUMP id DISP Dm VALVE Qn DP dp, or make the joint T 1 (a pivoted cylinder) or T 2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: an HMOTOR drive turns a revolute joint, but %2 is T %3</source>
        <translation>%1: an HMOTOR drive turns a revolute joint, but %2 is T %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>drive a T 1 or T 2 joint with D j CYL PUMP id BORE d ROD d VALVE Qn DP dp</source>
        <translation>drive a T 1 or T 2 joint with D j CYL PUMP id BORE d ROD d VALVE Qn DP dp</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: a CYL drive needs the stroke, but %2 has no %3</source>
        <translation>%1: a CYL drive needs the stroke, but %2 has no %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give the joint LL (fully retracted) and UL (fully extended): the chamber volumes follow from them</source>
        <translation>give the joint LL (fully retracted) and UL (fully extended): the chamber volumes follow from them</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: the stroke of %2 is empty (LL %3 ≥ UL %4)</source>
        <translation>%1: the stroke of %2 is empty (LL %3 ≥ UL %4)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>LL is the fully retracted and UL the fully extended coordinate</source>
        <translation>LL is the fully retracted and UL the fully extended coordinate</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: pump %2 is not defined</source>
        <translation>%1: pump %2 is not defined</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a PUMP id FLOW Qmax PRESSURE p_max statement</source>
        <translation>add a PUMP id FLOW Qmax PRESSURE p_max statement</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pumps are %1</source>
        <translation>the pumps are %1</translation>
    </message>
    <message>
        <location line="+11" />
        <location line="+71" />
        <source>%1: joint %2 is not defined</source>
        <translation>%1: joint %2 is not defined</translation>
    </message>
    <message>
        <location line="-70" />
        <location line="+71" />
        <source>use the id of a joint (C id …)</source>
        <translation>use the id of a joint (C id …)</translation>
    </message>
    <message>
        <location line="-65" />
        <source>%1 already has a drive (line %2)</source>
        <translation>%1 already has a drive (line %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>one joint takes one drive; remove one of them</source>
        <translation>one joint takes one drive; remove one of them</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: %2 is a free joint (T 3), which no drive can move</source>
        <translation>%1: %2 is a free joint (T 3), which no drive can move</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive a T 0, T 1 or T 2 joint; push a free body with a force (F … POINT) instead</source>
        <translation>drive a T 0, T 1 or T 2 joint; push a free body with a force (F … POINT) instead</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: PUMP/BORE/ROD describe a cylinder, but %2 is revolute</source>
        <translation>%1: PUMP/BORE/ROD describe a cylinder, but %2 is revolute</translation>
    </message>
    <message>
        <location line="+3" />
        <source>for a hydraulic motor give VMAX (rad/s) and FMAX (N·m); or make the joint T 1 or T 2</source>
        <translation>for a hydraulic motor give VMAX (rad/s) and FMAX (N·m); or make the joint T 1 or T 2</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: VI = %2 is faster than its hydraulic drive can move it (%3, from its pump and cylinder data)</source>
        <translation>%1: VI = %2 is faster than its hydraulic drive can move it (%3, from its pump and cylinder data)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: VI = %2 is faster than its hydraulic drive can move it (%3)</source>
        <translation>%1: VI = %2 is faster than its hydraulic drive can move it (%3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give |VI| ≤ flow / bore area (extending) or flow / annulus area (retracting)</source>
        <translation>give |VI| ≤ flow / bore area (extending) or flow / annulus area (retracting)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>give |VI| ≤ VMAX (extending) or VMIN (retracting)</source>
        <translation>give |VI| ≤ VMAX (extending) or VMIN (retracting)</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="+274" />
        <location filename="../solver/spec/validate.cpp" line="+10" />
        <location line="+178" />
        <source>force %1</source>
        <translation>force %1</translation>
    </message>
    <message>
        <location filename="../solver/spec/validate.cpp" line="-174" />
        <location line="+71" />
        <source>%1: body %2 is not defined</source>
        <translation>%1: body %2 is not defined</translation>
    </message>
    <message>
        <location line="-70" />
        <source>use the id of a body (B id …)</source>
        <translation>use the id of a body (B id …)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: joint %2 is a free joint (T 3), which has no single coordinate</source>
        <translation>%1: joint %2 is a free joint (T 3), which has no single coordinate</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a T 0, T 1 or T 2 joint here; load a free body with a force on the body (F … POINT or TORQUE)</source>
        <translation>use a T 0, T 1 or T 2 joint here; load a free body with a force on the body (F … POINT or TORQUE)</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+125" />
        <source>%1: %2 is negative</source>
        <translation>%1: %2 is negative</translation>
    </message>
    <message>
        <location line="-120" />
        <location line="+90" />
        <location line="+34" />
        <source>%1: %2 must be positive</source>
        <translation>%1: %2 must be positive</translation>
    </message>
    <message>
        <location line="-113" />
        <source>%1: the spring connects body %2 to itself</source>
        <translation>%1: the spring connects body %2 to itself</translation>
    </message>
    <message>
        <location line="+13" />
        <source>give the force's direction, e.g. DIR 0 0 -1</source>
        <translation>give the force's direction, e.g. DIR 0 0 -1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a stiffness is ≥ 0, in N/m</source>
        <translation>a stiffness is ≥ 0, in N/m</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a rest length is ≥ 0, in m</source>
        <translation>a rest length is ≥ 0, in m</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a damping is ≥ 0, in N s/m</source>
        <translation>a damping is ≥ 0, in N s/m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the reference area in m²</source>
        <translation>the reference area in m²</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a drag coefficient is ≥ 0</source>
        <translation>a drag coefficient is ≥ 0</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the fluid's density in kg/m³ (air: 1.225)</source>
        <translation>the fluid's density in kg/m³ (air: 1.225)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>use the id of a body (B id …), or 0 for the ground</source>
        <translation>use the id of a body (B id …), or 0 for the ground</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1: the PRISM's height H must be positive</source>
        <translation>%1: the PRISM's height H must be positive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>H is in metres</source>
        <translation>H is in metres</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: the PRISM's outline has no area</source>
        <translation>%1: the PRISM's outline has no area</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give at least three x y vertices that are not on one line</source>
        <translation>give at least three x y vertices that are not on one line</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: %2 dimension %3 must be positive, not %4</source>
        <translation>%1: %2 dimension %3 must be positive, not %4</translation>
    </message>
    <message>
        <location line="+5" />
        <source>dimensions are lengths in metres</source>
        <translation>dimensions are lengths in metres</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: the TUBE's inner radius is not smaller than its outer radius</source>
        <translation>%1: the TUBE's inner radius is not smaller than its outer radius</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write TUBE RO RI L with RI &lt; RO</source>
        <translation>write TUBE RO RI L with RI &lt; RO</translation>
    </message>
    <message>
        <location line="+5" />
        <source>SCALE 0.001 turns millimetres into metres</source>
        <translation>SCALE 0.001 turns millimetres into metres</translation>
    </message>
    <message>
        <location line="+17" />
        <source>give a direction, e.g. AXIS 1 0 0</source>
        <translation>give a direction, e.g. AXIS 1 0 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: the ROT axis has zero length</source>
        <translation>%1: the ROT axis has zero length</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write ROT ax ay az degrees, e.g. ROT 0 0 1 90</source>
        <translation>write ROT ax ay az degrees, e.g. ROT 0 0 1 90</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: COLOR components must lie between 0 and 1</source>
        <translation>%1: COLOR components must lie between 0 and 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write COLOR r g b with 0 ≤ r, g, b ≤ 1 (e.g. 0.8 0.1 0.1 for red)</source>
        <translation>write COLOR r g b with 0 ≤ r, g, b ≤ 1 (e.g. 0.8 0.1 0.1 for red)</translation>
    </message>
    <message>
        <location line="+19" />
        <source>the model has %1 bodies; Padrob takes at most %2</source>
        <translation>the model has %1 bodies; Padrob takes at most %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>split the machine into smaller models, or merge bodies that move together</source>
        <translation>split the machine into smaller models, or merge bodies that move together</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the model has %1 joints; Padrob takes at most %2</source>
        <translation>the model has %1 joints; Padrob takes at most %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>split the machine into smaller models, or remove joints that never move</source>
        <translation>split the machine into smaller models, or remove joints that never move</translation>
    </message>
    <message>
        <location filename="../solver/parse/lexer.cpp" line="+139" />
        <source>unexpected control character (code %1)</source>
        <translation>unexpected control character (code %1)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>delete it; a model file is plain text</source>
        <translation>delete it; a model file is plain text</translation>
    </message>
    <message>
        <location line="+35" />
        <source>the string has no closing quote</source>
        <translation>the string has no closing quote</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add '"' at the end of the text</source>
        <translation>add '"' at the end of the text</translation>
    </message>
    <message>
        <location filename="../solver/parse/parser.cpp" line="-1230" />
        <source>write %1</source>
        <translation>write %1</translation>
    </message>
    <message>
        <location line="+29" />
        <source>did you mean '%1'?</source>
        <translation>did you mean '%1'?</translation>
    </message>
    <message>
        <location line="+59" />
        <source>a statement cannot start with a string</source>
        <translation>a statement cannot start with a string</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a statement starts with a keyword, not with the number %1</source>
        <translation>a statement starts with a keyword, not with the number %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>start the line with GRAVITY, B, C, D, F or G, or join it to the line above</source>
        <translation>start the line with GRAVITY, B, C, D, F or G, or join it to the line above</translation>
    </message>
    <message>
        <location line="+21" />
        <source>unknown keyword '%1'</source>
        <translation>unknown keyword '%1'</translation>
    </message>
    <message>
        <location line="+86" />
        <source>%1: %2 is out of range</source>
        <translation>%1: %2 is out of range</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a number must lie within ±1.7e308</source>
        <translation>a number must lie within ±1.7e308</translation>
    </message>
    <message>
        <location line="+3" />
        <source>numbers look like 12, -0.5, .2 or 1e-3</source>
        <translation>numbers look like 12, -0.5, .2 or 1e-3</translation>
    </message>
    <message>
        <location line="+15" />
        <location line="+42" />
        <location line="+271" />
        <source>%1: %2 is missing</source>
        <translation>%1: %2 is missing</translation>
    </message>
    <message>
        <location line="-309" />
        <source>%1: expected %2, found '%3'</source>
        <translation>%1: expected %2, found '%3'</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1: %2 needs %3 numbers, only %4 given</source>
        <translation>%1: %2 needs %3 numbers, only %4 given</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: %2 needs %3 numbers, the line ends</source>
        <translation>%1: %2 needs %3 numbers, the line ends</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: %2 needs %3 numbers, found '%4'</source>
        <translation>%1: %2 needs %3 numbers, found '%4'</translation>
    </message>
    <message>
        <location line="+17" />
        <source>%1: %2 is missing, found '%3'</source>
        <translation>%1: %2 is missing, found '%3'</translation>
    </message>
    <message>
        <location line="+16" />
        <location line="+810" />
        <location line="+112" />
        <source>%1: %2 cannot be negative (%3)</source>
        <translation>%1: %2 cannot be negative (%3)</translation>
    </message>
    <message>
        <location line="-921" />
        <location line="+4" />
        <source>ids are whole numbers 0, 1, 2, …</source>
        <translation>ids are whole numbers 0, 1, 2, …</translation>
    </message>
    <message>
        <location line="-1" />
        <source>%1: %2 must be a whole number, not %3</source>
        <translation>%1: %2 must be a whole number, not %3</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: %2 %3 is too large</source>
        <translation>%1: %2 %3 is too large</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ids go from 0 to %1</source>
        <translation>ids go from 0 to %1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>write MAG value, MAG SIN amp freq phase [offset], MAG TABLE T t1 v1 t2 v2 … or MAG TABLE Q joint q1 v1 …</source>
        <translation>write MAG value, MAG SIN amp freq phase [offset], MAG TABLE T t1 v1 t2 v2 … or MAG TABLE Q joint q1 v1 …</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the magnitude</source>
        <translation>the magnitude</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the offset</source>
        <translation>the offset</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the joint of TABLE Q</source>
        <translation>the joint of TABLE Q</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: TABLE must say T (by time) or Q (by a joint's coordinate)</source>
        <translation>%1: TABLE must say T (by time) or Q (by a joint's coordinate)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write TABLE T t1 v1 t2 v2 … or TABLE Q joint q1 v1 q2 v2 …</source>
        <translation>write TABLE T t1 v1 t2 v2 … or TABLE Q joint q1 v1 q2 v2 …</translation>
    </message>
    <message>
        <location line="+10" />
        <source>a table value</source>
        <translation>a table value</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: a TABLE needs pairs of numbers (abscissa value), found %2 number</source>
        <translation>%1: a TABLE needs pairs of numbers (abscissa value), found %2 number</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: a TABLE needs pairs of numbers (abscissa value), found %2 numbers</source>
        <translation>%1: a TABLE needs pairs of numbers (abscissa value), found %2 numbers</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: table abscissae must increase (%2 follows %3)</source>
        <translation>%1: table abscissae must increase (%2 follows %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>sort the pairs by their first number and remove repeats</source>
        <translation>sort the pairs by their first number and remove repeats</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1: MAG needs a value</source>
        <translation>%1: MAG needs a value</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: MAG needs a value, found '%2'</source>
        <translation>%1: MAG needs a value, found '%2'</translation>
    </message>
    <message>
        <location line="+28" />
        <source>%1: unexpected number %2</source>
        <translation>%1: unexpected number %2</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+11" />
        <source>remove it</source>
        <translation>remove it</translation>
    </message>
    <message>
        <location line="-10" />
        <source>remove it, or put an option before it (%1)</source>
        <translation>remove it, or put an option before it (%1)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: '%2' is not an option of %3</source>
        <translation>%1: '%2' is not an option of %3</translation>
    </message>
    <message>
        <location line="+6" />
        <source>options are %1</source>
        <translation>options are %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>write %1 %2</source>
        <translation>write %1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 after %2</source>
        <translation>%1 after %2</translation>
    </message>
    <message>
        <location line="+30" />
        <source>%1: %2 needs a word</source>
        <translation>%1: %2 needs a word</translation>
    </message>
    <message>
        <location line="+17" />
        <location line="+5" />
        <source>%1: %2 needs a text in double quotes</source>
        <translation>%1: %2 needs a text in double quotes</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+431" />
        <source>%1: %2 is given twice</source>
        <translation>%1: %2 is given twice</translation>
    </message>
    <message>
        <location line="-430" />
        <location line="+431" />
        <source>keep one %1</source>
        <translation>keep one %1</translation>
    </message>
    <message>
        <location line="-389" />
        <source>write GRAVITY gx gy gz (m/s², z is up)</source>
        <translation>write GRAVITY gx gy gz (m/s², z is up)</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+22" />
        <location line="+21" />
        <source>%1 is given twice (first at line %2)</source>
        <translation>%1 is given twice (first at line %2)</translation>
    </message>
    <message>
        <location line="-40" />
        <location line="+22" />
        <location line="+19" />
        <source>keep one %1 statement</source>
        <translation>keep one %1 statement</translation>
    </message>
    <message>
        <location line="-27" />
        <location line="+77" />
        <source>the coefficient of restitution</source>
        <translation>the coefficient of restitution</translation>
    </message>
    <message>
        <location line="-76" />
        <source>write RESTITUTION e (0 inelastic … 1 elastic)</source>
        <translation>write RESTITUTION e (0 inelastic … 1 elastic)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>RESTITUTION %1 is outside 0 … 1</source>
        <translation>RESTITUTION %1 is outside 0 … 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>0 stops a joint dead at its limit, 1 bounces it back at the same speed</source>
        <translation>0 stops a joint dead at its limit, 1 bounces it back at the same speed</translation>
    </message>
    <message>
        <location line="+32" />
        <source>the bulk modulus in Pa</source>
        <translation>the bulk modulus in Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the laminar pressure difference in Pa</source>
        <translation>the laminar pressure difference in Pa</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the effective bulk modulus of oil in hoses is about 1e9 Pa</source>
        <translation>the effective bulk modulus of oil in hoses is about 1e9 Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a few bar, e.g. LAMINAR 2e5</source>
        <translation>a few bar, e.g. LAMINAR 2e5</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the friction coefficient</source>
        <translation>the friction coefficient</translation>
    </message>
    <message>
        <location line="+7" />
        <source>CONTACT MU %1 is negative</source>
        <translation>CONTACT MU %1 is negative</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MU is the Coulomb friction coefficient, 0 (frictionless) or more: steel on steel about 0.2 … 0.6</source>
        <translation>MU is the Coulomb friction coefficient, 0 (frictionless) or more: steel on steel about 0.2 … 0.6</translation>
    </message>
    <message>
        <location line="+10" />
        <source>CONTACT E %1 is outside 0 … 1</source>
        <translation>CONTACT E %1 is outside 0 … 1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>0 stops a solid dead where it hits, 1 bounces it back at the same speed</source>
        <translation>0 stops a solid dead where it hits, 1 bounces it back at the same speed</translation>
    </message>
    <message>
        <location line="+15" />
        <source>pump</source>
        <translation>pump</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+425" />
        <location line="+14" />
        <source>the pump id</source>
        <translation>the pump id</translation>
    </message>
    <message>
        <location line="-435" />
        <source>pump %1</source>
        <translation>pump %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the largest flow in m³/s</source>
        <translation>the largest flow in m³/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the pressure setting in Pa</source>
        <translation>the pressure setting in Pa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load-sensing margin in Pa</source>
        <translation>the load-sensing margin in Pa</translation>
    </message>
    <message>
        <location line="+10" />
        <source>FLOW in m³/s (45 cm³/rev at 1480 rpm is 1.11e-3), PRESSURE and MARGIN in Pa</source>
        <translation>FLOW in m³/s (45 cm³/rev at 1480 rpm is 1.11e-3), PRESSURE and MARGIN in Pa</translation>
    </message>
    <message>
        <location line="+8" />
        <source>pump %1 is defined twice (first at line %2)</source>
        <translation>pump %1 is defined twice (first at line %2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give each pump its own id</source>
        <translation>give each pump its own id</translation>
    </message>
    <message>
        <location line="+13" />
        <location line="+519" />
        <source>body</source>
        <translation>body</translation>
    </message>
    <message>
        <location line="-519" />
        <location line="+188" />
        <location line="+455" />
        <source>the body id</source>
        <translation>the body id</translation>
    </message>
    <message>
        <location line="-619" />
        <source>%1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found %2</source>
        <translation>%1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz Ixz]), found %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>give the mass and the three moments of inertia: %1</source>
        <translation>give the mass and the three moments of inertia: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give all three products of inertia Ixy Iyz Ixz, or none</source>
        <translation>give all three products of inertia Ixy Iyz Ixz, or none</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove the extra numbers</source>
        <translation>remove the extra numbers</translation>
    </message>
    <message>
        <location line="+20" />
        <source>a body statement (B)</source>
        <translation>a body statement (B)</translation>
    </message>
    <message>
        <location line="+17" />
        <location line="+5" />
        <source>joint</source>
        <translation>joint</translation>
    </message>
    <message>
        <location line="-5" />
        <location line="+165" />
        <location line="+327" />
        <source>the joint id</source>
        <translation>the joint id</translation>
    </message>
    <message>
        <location line="-484" />
        <source>the lower limit</source>
        <translation>the lower limit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the upper limit</source>
        <translation>the upper limit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the initial coordinate</source>
        <translation>the initial coordinate</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the initial rate</source>
        <translation>the initial rate</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a joint statement (C)</source>
        <translation>a joint statement (C)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: there is no joint type T %2</source>
        <translation>%1: there is no joint type T %2</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: DEG after %2, but the coordinate of %3 is a length</source>
        <translation>%1: DEG after %2, but the coordinate of %3 is a length</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a pivoted linear actuator (T 1)</source>
        <translation>a pivoted linear actuator (T 1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a prismatic joint (T 2)</source>
        <translation>a prismatic joint (T 2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove DEG; give the value in metres</source>
        <translation>remove DEG; give the value in metres</translation>
    </message>
    <message>
        <location line="+21" />
        <source>%1 must follow a joint statement (C)</source>
        <translation>%1 must follow a joint statement (C)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it right after its joint's C line (blank and comment lines may come between)</source>
        <translation>put it right after its joint's C line (blank and comment lines may come between)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>joint %1, B%2</source>
        <translation>joint %1, B%2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>joint %1 already has a B%2 line (line %3)</source>
        <translation>joint %1 already has a B%2 line (line %3)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>keep one B%1 line per joint</source>
        <translation>keep one B%1 line per joint</translation>
    </message>
    <message>
        <location line="+24" />
        <source>%1: %2 belongs on the B%3 line</source>
        <translation>%1: %2 belongs on the B%3 line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>on the B%1 line write %2</source>
        <translation>on the B%1 line write %2</translation>
    </message>
    <message>
        <location line="+8" />
        <source>a B%1 line</source>
        <translation>a B%1 line</translation>
    </message>
    <message>
        <location line="+20" />
        <source>a CL1/CL2 line</source>
        <translation>a CL1/CL2 line</translation>
    </message>
    <message>
        <location line="+22" />
        <source>drive</source>
        <translation>drive</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the drive kind is missing</source>
        <translation>%1: the drive kind is missing</translation>
    </message>
    <message>
        <location line="+7" />
        <source>speed</source>
        <translation>speed</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+261" />
        <source>force</source>
        <translation>force</translation>
    </message>
    <message>
        <location line="-260" />
        <location line="+138" />
        <location line="+1" />
        <source>diameter</source>
        <translation>diameter</translation>
    </message>
    <message>
        <location line="-139" />
        <source>gain</source>
        <translation>gain</translation>
    </message>
    <message>
        <location line="+40" />
        <source>write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa</source>
        <translation>write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n BORE d ROD d PRESSURE Pa</translation>
    </message>
    <message>
        <location line="-35" />
        <source>stall torque</source>
        <translation>stall torque</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no-load speed</source>
        <translation>no-load speed</translation>
    </message>
    <message>
        <location line="+25" />
        <source>%1: unknown drive kind '%2'</source>
        <translation>%1: unknown drive kind '%2'</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+119" />
        <source>a %1 drive</source>
        <translation>a %1 drive</translation>
    </message>
    <message>
        <location line="-99" />
        <source>%1: give either VMAX/FMAX or the hydraulic data PUMP … PRESSURE, not both</source>
        <translation>%1: give either VMAX/FMAX or the hydraulic data PUMP … PRESSURE, not both</translation>
    </message>
    <message>
        <location line="+2" />
        <source>remove one of the two forms</source>
        <translation>remove one of the two forms</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1: %2 follows from the hydraulic data PUMP … PRESSURE</source>
        <translation>%1: %2 follows from the hydraulic data PUMP … PRESSURE</translation>
    </message>
    <message>
        <location line="+3" />
        <source>remove %1, or give VMAX/VMIN/FMAX/FMIN instead of the pump data</source>
        <translation>remove %1, or give VMAX/VMIN/FMAX/FMIN instead of the pump data</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+154" />
        <source>%1: the rod (%2 m) is not thinner than the bore (%3 m)</source>
        <translation>%1: the rod (%2 m) is not thinner than the bore (%3 m)</translation>
    </message>
    <message>
        <location line="-150" />
        <location line="+154" />
        <source>ROD and BORE are diameters in metres; the rod must be thinner</source>
        <translation>ROD and BORE are diameters in metres; the rod must be thinner</translation>
    </message>
    <message>
        <location line="-149" />
        <source>%1: a hydraulic drive needs VMAX or the pump data</source>
        <translation>%1: a hydraulic drive needs VMAX or the pump data</translation>
    </message>
    <message>
        <location line="-438" />
        <location line="+68" />
        <location line="+385" />
        <location line="+106" />
        <location line="+12" />
        <source>%1: %2 must be positive, not %3</source>
        <translation>%1: %2 must be positive, not %3</translation>
    </message>
    <message>
        <location line="-1086" />
        <source>statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C (with B1, B2, CL1), D, F and G; comments start with // or #</source>
        <translation>statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C (with B1, B2, CL1), D, F and G; comments start with // or #</translation>
    </message>
    <message>
        <location line="+682" />
        <source>the joint type (0, 1, 2 or 3)</source>
        <translation>the joint type (0, 1, 2 or 3)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 (prismatic) or T 3 (free body)</source>
        <translation>use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 (prismatic) or T 3 (free body)</translation>
    </message>
    <message>
        <location line="+145" />
        <source>write HYD, MOTOR, PNEU, SERVO, CYL or HMOTOR after the joint id</source>
        <translation>write HYD, MOTOR, PNEU, SERVO, CYL or HMOTOR after the joint id</translation>
    </message>
    <message>
        <location line="+39" />
        <source>drive kinds are HYD, MOTOR, PNEU, SERVO, CYL and HMOTOR</source>
        <translation>drive kinds are HYD, MOTOR, PNEU, SERVO, CYL and HMOTOR</translation>
    </message>
    <message>
        <location line="+83" />
        <source>give its magnitude; the direction comes from the operator's command</source>
        <translation>give its magnitude; the direction comes from the operator's command</translation>
    </message>
    <message>
        <location line="+5" />
        <source>gains are zero or positive</source>
        <translation>gains are zero or positive</translation>
    </message>
    <message>
        <location line="+14" />
        <source>two volumes in m³</source>
        <translation>two volumes in m³</translation>
    </message>
    <message>
        <location line="+1" />
        <source>two pressures in Pa</source>
        <translation>two pressures in Pa</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+13" />
        <source>the nominal flow in m³/s</source>
        <translation>the nominal flow in m³/s</translation>
    </message>
    <message>
        <location line="-12" />
        <location line="+13" />
        <source>the nominal pressure drop in Pa</source>
        <translation>the nominal pressure drop in Pa</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+13" />
        <source>the spool time constant in s</source>
        <translation>the spool time constant in s</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+13" />
        <source>the viscous friction</source>
        <translation>the viscous friction</translation>
    </message>
    <message>
        <location line="-6" />
        <source>the displacement in m³/rad</source>
        <translation>the displacement in m³/rad</translation>
    </message>
    <message>
        <location line="+26" />
        <source>%1: %2 belongs to the prescribed-rate HYD drive, not to %3</source>
        <translation>%1: %2 belongs to the prescribed-rate HYD drive, not to %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a CYL drive's speed follows from VALVE and BORE, its force from the PUMP's PRESSURE; remove %1 or write the drive as HYD</source>
        <translation>a CYL drive's speed follows from VALVE and BORE, its force from the PUMP's PRESSURE; remove %1 or write the drive as HYD</translation>
    </message>
    <message>
        <location line="+3" />
        <source>an HMOTOR drive's speed follows from VALVE and DISP, its torque from the PUMP's PRESSURE; remove %1 or write the drive as HYD</source>
        <translation>an HMOTOR drive's speed follows from VALVE and DISP, its torque from the PUMP's PRESSURE; remove %1 or write the drive as HYD</translation>
    </message>
    <message>
        <location line="+20" />
        <source>%1: COMP %2 is not a compensation</source>
        <translation>%1: COMP %2 is not a compensation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write COMP NONE (orifice law), PRE (pre-compensated) or POST (post-compensated, flow sharing)</source>
        <translation>write COMP NONE (orifice law), PRE (pre-compensated) or POST (post-compensated, flow sharing)</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: P0 %2 is below tank pressure (0)</source>
        <translation>%1: P0 %2 is below tank pressure (0)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>pressures are gauge pressures in Pa, 0 or more</source>
        <translation>pressures are gauge pressures in Pa, 0 or more</translation>
    </message>
    <message>
        <location line="+1" />
        <source>volumes in m³, e.g. 5e-4 for half a litre of hose</source>
        <translation>volumes in m³, e.g. 5e-4 for half a litre of hose</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the spool's time constant in seconds, e.g. TAU 0.05</source>
        <translation>the spool's time constant in seconds, e.g. TAU 0.05</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give its magnitude in SI units</source>
        <translation>give its magnitude in SI units</translation>
    </message>
    <message>
        <location line="+26" />
        <source>the force id</source>
        <translation>the force id</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: the force kind is missing</source>
        <translation>%1: the force kind is missing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write POINT, TORQUE, JOINT, SPRING or AERO after the force id</source>
        <translation>write POINT, TORQUE, JOINT, SPRING or AERO after the force id</translation>
    </message>
    <message>
        <location line="+6" />
        <source>coefficient</source>
        <translation>coefficient</translation>
    </message>
    <message>
        <location line="+13" />
        <source>stiffness</source>
        <translation>stiffness</translation>
    </message>
    <message>
        <location line="+1" />
        <source>length</source>
        <translation>length</translation>
    </message>
    <message>
        <location line="+1" />
        <source>damping</source>
        <translation>damping</translation>
    </message>
    <message>
        <location line="+3" />
        <source>area</source>
        <translation>area</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+96" />
        <source>density</source>
        <translation>density</translation>
    </message>
    <message>
        <location line="-59" />
        <source>%1: unknown force kind '%2'</source>
        <translation>%1: unknown force kind '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>force kinds are POINT, TORQUE, JOINT, SPRING and AERO</source>
        <translation>force kinds are POINT, TORQUE, JOINT, SPRING and AERO</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a %1 force</source>
        <translation>a %1 force</translation>
    </message>
    <message>
        <location line="+38" />
        <source>graphic</source>
        <translation>graphic</translation>
    </message>
    <message>
        <location line="+0" />
        <source>the graphic id</source>
        <translation>the graphic id</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: B body is missing after the id</source>
        <translation>%1: B body is missing after the id</translation>
    </message>
    <message>
        <location line="+10" />
        <source>mass</source>
        <translation>mass</translation>
    </message>
    <message>
        <location line="+3" />
        <source>factor</source>
        <translation>factor</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: the shape is missing</source>
        <translation>%1: the shape is missing</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH and its dimensions</source>
        <translation>write BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH and its dimensions</translation>
    </message>
    <message>
        <location line="+25" />
        <source>%1: unknown shape '%2'</source>
        <translation>%1: unknown shape '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>shapes are BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM and MESH</source>
        <translation>shapes are BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM and MESH</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 dimension %2 of %3 (%4)</source>
        <translation>%1 dimension %2 of %3 (%4)</translation>
    </message>
    <message>
        <location line="+12" />
        <source>a PRISM value</source>
        <translation>a PRISM value</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1: PRISM needs its height H and at least three x y vertices, found %2 numbers</source>
        <translation>%1: PRISM needs its height H and at least three x y vertices, found %2 numbers</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: the MESH file name must be in double quotes</source>
        <translation>%1: the MESH file name must be in double quotes</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: MESH needs a file name in double quotes</source>
        <translation>%1: MESH needs a file name in double quotes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write MESH "meshes/part.stl" (relative to the model file)</source>
        <translation>write MESH "meshes/part.stl" (relative to the model file)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a graphic (G)</source>
        <translation>a graphic (G)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1: give MASS or RHO, not both</source>
        <translation>%1: give MASS or RHO, not both</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MASS is the solid's mass in kg; RHO its density in kg/m³</source>
        <translation>MASS is the solid's mass in kg; RHO its density in kg/m³</translation>
    </message>
    <message>
        <location filename="../solver/integrate/integrator.cpp" line="+73" />
        <source>the right-hand side reported a failure at t = %1 s</source>
        <translation>the right-hand side reported a failure at t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the right-hand side gave a non-finite value in component %1 (%2) at t = %3 s</source>
        <translation>the right-hand side gave a non-finite value in component %1 (%2) at t = %3 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the right-hand side threw an exception at t = %1 s</source>
        <translation>the right-hand side threw an exception at t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the event functions reported a failure at t = %1 s</source>
        <translation>the event functions reported a failure at t = %1 s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>event function %1 is not finite (%2) at t = %3 s</source>
        <translation>event function %1 is not finite (%2) at t = %3 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the event functions threw an exception at t = %1 s</source>
        <translation>the event functions threw an exception at t = %1 s</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 at t = %2 s</source>
        <translation>%1 at t = %2 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 at t = %2 s [%3]</source>
        <translation>%1 at t = %2 s [%3]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 at t = %2 s: %3</source>
        <translation>%1 at t = %2 s: %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 at t = %2 s: %3 [%4]</source>
        <translation>%1 at t = %2 s: %3 [%4]</translation>
    </message>
    <message>
        <location filename="../solver/integrate/simulation.cpp" line="-1" />
        <source>the ground</source>
        <translation>the ground</translation>
    </message>
    <message>
        <location line="+2" />
        <source>body %1 %2</source>
        <translation>body %1 %2</translation>
    </message>
    <message>
        <location line="+23" />
        <source>t=%1 s: %2 welded to %3</source>
        <translation>t=%1 s: %2 welded to %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>t=%1 s: %2 released from %3</source>
        <translation>t=%1 s: %2 released from %3</translation>
    </message>
    <message>
        <location line="+5" />
        <source>t=%1 s: pump %2 saturated: the valves ask for %3 L/min, more than it gives</source>
        <translation>t=%1 s: pump %2 saturated: the valves ask for %3 L/min, more than it gives</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: pump %2 no longer saturated (%3 L/min asked)</source>
        <translation>t=%1 s: pump %2 no longer saturated (%3 L/min asked)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>t=%1 s: joint %2 cavitates: a chamber's pressure fell to 0 (the load runs ahead of the oil)</source>
        <translation>t=%1 s: joint %2 cavitates: a chamber's pressure fell to 0 (the load runs ahead of the oil)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>t=%1 s: joint %2 no longer cavitates</source>
        <translation>t=%1 s: joint %2 no longer cavitates</translation>
    </message>
    <message>
        <location line="+13" />
        <source>t=%1 s: %2 and %3 overlap by %4 mm, deeper than the contact pushes back for (a drive stronger than the contact, or a fast hit): they are pushed apart gently</source>
        <translation>t=%1 s: %2 and %3 overlap by %4 mm, deeper than the contact pushes back for (a drive stronger than the contact, or a fast hit): they are pushed apart gently</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: %2 and %3 no longer overlap deeply (%4 mm)</source>
        <translation>t=%1 s: %2 and %3 no longer overlap deeply (%4 mm)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>t=%1 s: the closed loops (closing joints %2) locked up: a singular configuration, the mechanism cannot move on</source>
        <translation>t=%1 s: the closed loops (closing joints %2) locked up: a singular configuration, the mechanism cannot move on</translation>
    </message>
    <message>
        <location line="+19" />
        <source>t=%1 s: joint %2 hit its lower limit %3 %4</source>
        <translation>t=%1 s: joint %2 hit its lower limit %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 hit its upper limit %3 %4</source>
        <translation>t=%1 s: joint %2 hit its upper limit %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 left its lower limit %3 %4</source>
        <translation>t=%1 s: joint %2 left its lower limit %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 left its upper limit %3 %4</source>
        <translation>t=%1 s: joint %2 left its upper limit %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 relief valve opened extending at %3 %4</source>
        <translation>t=%1 s: joint %2 relief valve opened extending at %3 %4</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 relief valve opened retracting at %3 %4</source>
        <translation>t=%1 s: joint %2 relief valve opened retracting at %3 %4</translation>
    </message>
    <message>
        <location line="+3" />
        <source>t=%1 s: joint %2 relief valve closed extending</source>
        <translation>t=%1 s: joint %2 relief valve closed extending</translation>
    </message>
    <message>
        <location line="+1" />
        <source>t=%1 s: joint %2 relief valve closed retracting</source>
        <translation>t=%1 s: joint %2 relief valve closed retracting</translation>
    </message>
    <message>
        <location line="+823" />
        <source>the closed loops locked up at t = %1 s (a singular configuration: the loop-closure equations lost rank, so the mechanism cannot move on there); drive it another way or change the geometry</source>
        <translation>the closed loops locked up at t = %1 s (a singular configuration: the loop-closure equations lost rank, so the mechanism cannot move on there); drive it another way or change the geometry</translation>
    </message>
    <message>
        <location line="+30" />
        <source>the likely cause: spring force %1 (K = %2 N/m on a body of %3 kg, a natural period of %4 s) is too stiff for the step of %5 s; use a step under %6 s or the adaptive integrator, or soften the spring</source>
        <translation>the likely cause: spring force %1 (K = %2 N/m on a body of %3 kg, a natural period of %4 s) is too stiff for the step of %5 s; use a step under %6 s or the adaptive integrator, or soften the spring</translation>
    </message>
    <message>
        <location line="+10" />
        <source>the likely cause: a spring, force or hydraulic drive too stiff for the step of %1 s, or a body too light for the forces on it; try a smaller step or the adaptive integrator, and check the masses and force magnitudes</source>
        <translation>the likely cause: a spring, force or hydraulic drive too stiff for the step of %1 s, or a body too light for the forces on it; try a smaller step or the adaptive integrator, and check the masses and force magnitudes</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the likely cause: a force or spring that grows without bound, or a body too light for the forces on it; check the masses and force magnitudes</source>
        <translation>the likely cause: a force or spring that grows without bound, or a body too light for the forces on it; check the masses and force magnitudes</translation>
    </message>
    <message>
        <location line="+39" />
        <source>the closed loops cannot be closed at t = %1 s from the coordinates given: set coordinates the loops can reach</source>
        <translation>the closed loops cannot be closed at t = %1 s from the coordinates given: set coordinates the loops can reach</translation>
    </message>
    <message>
        <location line="+33" />
        <source>the simulation failed at t = %1 s: the pressures of the drive on joint %2 are no longer finite (%3); check its volumes, valve and pump data</source>
        <translation>the simulation failed at t = %1 s: the pressures of the drive on joint %2 are no longer finite (%3); check its volumes, valve and pump data</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the simulation failed at t = %1 s: %2</source>
        <translation>the simulation failed at t = %1 s: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the simulation failed at t = %1 s, joint %2: %3; %4</source>
        <translation>the simulation failed at t = %1 s, joint %2: %3; %4</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the simulation failed at t = %1 s, joint %2 (%3): %4; %5</source>
        <translation>the simulation failed at t = %1 s, joint %2 (%3): %4; %5</translation>
    </message>
    <message>
        <location line="+53" />
        <source>more than %1 events before t = %2 s: the joints keep switching (chattering)</source>
        <translation>more than %1 events before t = %2 s: the joints keep switching (chattering)</translation>
    </message>
    <message>
        <location line="+49" />
        <source>cannot weld: no such body</source>
        <translation>cannot weld: no such body</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot weld %1 to itself</source>
        <translation>cannot weld %1 to itself</translation>
    </message>
    <message>
        <location line="+5" />
        <source>cannot weld %1 to %2: %3 is already welded (release that weld first)</source>
        <translation>cannot weld %1 to %2: %3 is already welded (release that weld first)</translation>
    </message>
    <message>
        <location line="+36" />
        <source>cannot release: %1 is not welded to %2</source>
        <translation>cannot release: %1 is not welded to %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>cannot release: no such body</source>
        <translation>cannot release: no such body</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="+40" />
        <location filename="../solver/io/csv_writer.cpp" line="+36" />
        <source>no output file given</source>
        <translation>no output file given</translation>
    </message>
    <message>
        <location line="+2" />
        <source>cannot write %1: it is a folder</source>
        <translation>cannot write %1: it is a folder</translation>
    </message>
    <message>
        <location line="+9" />
        <source>cannot write %1: it is %2, which this run reads; give another output file</source>
        <translation>cannot write %1: it is %2, which this run reads; give another output file</translation>
    </message>
    <message>
        <location line="+45" />
        <location line="+6" />
        <location line="+13" />
        <source>cannot create %1: %2</source>
        <translation>cannot create %1: %2</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+38" />
        <location line="+72" />
        <source>cannot write to standard output: %1</source>
        <translation>cannot write to standard output: %1</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="-34" />
        <location line="+41" />
        <location line="+3" />
        <location line="+6" />
        <location line="+1" />
        <location line="+5" />
        <location line="+14" />
        <location line="+4" />
        <location line="+3" />
        <location line="+8" />
        <location line="+23" />
        <location filename="../solver/io/csv_writer.cpp" line="-71" />
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+8" />
        <source>the header was written in the middle of a row</source>
        <translation>the header was written in the middle of a row</translation>
    </message>
    <message>
        <location line="+33" />
        <source>a row has %1 values; the header has %2 columns</source>
        <translation>a row has %1 values; the header has %2 columns</translation>
    </message>
    <message>
        <location filename="../solver/core/output_file.cpp" line="-69" />
        <location filename="../solver/io/csv_writer.cpp" line="+21" />
        <source>the output was already closed</source>
        <translation>the output was already closed</translation>
    </message>
    <message>
        <location filename="../solver/io/csv_writer.cpp" line="+4" />
        <source>the last row is not finished</source>
        <translation>the last row is not finished</translation>
    </message>
    <message>
        <location filename="../solver/contact/contact_geometry.cpp" line="+127" />
        <source>G %1 cannot serve as a contact shape: %2</source>
        <translation>G %1 cannot serve as a contact shape: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>fix the mesh file, or mark the graphic NOCONTACT (drawn only)</source>
        <translation>fix the mesh file, or mark the graphic NOCONTACT (drawn only)</translation>
    </message>
    <message>
        <location line="+57" />
        <source>G %1 and %2 overlap by %3 mm at the initial pose: they never touch each other</source>
        <translation>G %1 and %2 overlap by %3 mm at the initial pose: they never touch each other</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../solver/integrate/simulation.cpp" line="-1155" />
        <source>scene G %1</source>
        <translation>scene G %1</translation>
    </message>
    <message>
        <location line="+0" />
        <location filename="../solver/integrate/simulation.cpp" line="+0" />
        <source>G %1</source>
        <translation>G %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>a pin in its bore is meant to; solids placed inside each other by mistake: move one out</source>
        <translation>a pin in its bore is meant to; solids placed inside each other by mistake: move one out</translation>
    </message>
    <message>
        <location line="+4" />
        <source>these solids are not joined to each other: they start inside each other and will pass through each other; move one out (or mark one NOCONTACT if it is only drawn)</source>
        <translation>these solids are not joined to each other: they start inside each other and will pass through each other; move one out (or mark one NOCONTACT if it is only drawn)</translation>
    </message>
</context>
<context>
    <name>DriveControls</name>
    <message>
        <location filename="../ide/studio/train/drive_controls.cpp" line="+35" />
        <source>left stick right + / left −</source>
        <translation>left stick right + / left −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left stick left + / right −</source>
        <translation>left stick left + / right −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>left stick up + / down −</source>
        <translation>left stick up + / down −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left stick down + / up −</source>
        <translation>left stick down + / up −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right stick right + / left −</source>
        <translation>right stick right + / left −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right stick left + / right −</source>
        <translation>right stick left + / right −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right stick up + / down −</source>
        <translation>right stick up + / down −</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right stick down + / up −</source>
        <translation>right stick down + / up −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>left trigger +</source>
        <translation>left trigger +</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left trigger −</source>
        <translation>left trigger −</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right trigger +</source>
        <translation>right trigger +</translation>
    </message>
    <message>
        <location line="+0" />
        <source>right trigger −</source>
        <translation>right trigger −</translation>
    </message>
    <message>
        <location line="+3" />
        <source>gamepad axis %1</source>
        <translation>gamepad axis %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>+ closes / − opens</source>
        <translation>+ closes / − opens</translation>
    </message>
    <message>
        <location line="+1" />
        <source>+ opens / − closes</source>
        <translation>+ opens / − closes</translation>
    </message>
    <message>
        <location line="+17" />
        <source>+ up / − down</source>
        <translation>+ up / − down</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ down / − up</source>
        <translation>+ down / − up</translation>
    </message>
    <message>
        <location line="+6" />
        <source>+ out / − in</source>
        <translation>+ out / − in</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ in / − out</source>
        <translation>+ in / − out</translation>
    </message>
    <message>
        <location line="+2" />
        <source>+ right / − left</source>
        <translation>+ right / − left</translation>
    </message>
    <message>
        <location line="+0" />
        <source>+ left / − right</source>
        <translation>+ left / − right</translation>
    </message>
    <message>
        <location line="+12" />
        <source>%1 + / %2 −</source>
        <comment>the key giving the drive +, the one giving −</comment>
        <translation>%1 + / %2 −</translation>
    </message>
    <message>
        <location line="+4" />
        <source>joystick axis %1</source>
        <translation>joystick axis %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>joystick axis %1 reversed</source>
        <translation>joystick axis %1 reversed</translation>
    </message>
    <message>
        <location line="+3" />
        <source>lever %1</source>
        <translation>lever %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>lever %1 reversed</source>
        <translation>lever %1 reversed</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 (bank %2)</source>
        <translation>%1 (bank %2)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 (%2)</source>
        <comment>a drive and which way + moves it</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no control</source>
        <translation>no control</translation>
    </message>
</context>
<context>
    <name>StationNode</name>
    <message>
        <location filename="../trainer/centre/station_node.cpp" line="+41" />
        <source>A station needs at least one tutorial to run.</source>
        <translation>A station needs at least one tutorial to run.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>A station needs a name, unique in the centre.</source>
        <translation>A station needs a name, unique in the centre.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The tutorials of one station must all use the same model: %1 uses %2, %3 uses %4.</source>
        <translation>The tutorials of one station must all use the same model: %1 uses %2, %3 uses %4.</translation>
    </message>
    <message>
        <location line="+105" />
        <source>the records journal takes writes again</source>
        <translation>the records journal takes writes again</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the records journal refuses writes: %1</source>
        <translation>the records journal refuses writes: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>%n pending attempt(s) recorded in the journal</source>
        <translation>
            <numerusform>%n pending attempt recorded in the journal</numerusform>
            <numerusform>%n pending attempts recorded in the journal</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TutorialRunner</name>
    <message>
        <location filename="../trainer/training/runner.cpp" line="+46" />
        <source>Autopilot console</source>
        <translation>Autopilot console</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Lever %1</source>
        <translation>Lever %1</translation>
    </message>
    <message>
        <location line="+146" />
        <source>line %1: %2</source>
        <translation>line %1: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>expected id=value, found "%1"</source>
        <translation>expected id=value, found "%1"</translation>
    </message>
    <message>
        <location line="+7" />
        <source>"%1" is not a joint id</source>
        <translation>"%1" is not a joint id</translation>
    </message>
    <message>
        <location line="+10" />
        <source>"%1" is not a number</source>
        <translation>"%1" is not a number</translation>
    </message>
    <message>
        <location line="+2" />
        <source>wait must not be negative</source>
        <translation>wait must not be negative</translation>
    </message>
    <message>
        <location line="+3" />
        <source>tol must be greater than 0</source>
        <translation>tol must be greater than 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>ramp must be greater than 0</source>
        <translation>ramp must be greater than 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>stall must be greater than 0</source>
        <translation>stall must be greater than 0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>lever must be greater than 0 and at most 1</source>
        <translation>lever must be greater than 0 and at most 1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>"%1" is not a joint id, wait, tol, lever, ramp or stall</source>
        <translation>"%1" is not a joint id, wait, tol, lever, ramp or stall</translation>
    </message>
    <message>
        <location line="+5" />
        <source>line %1: lever=, ramp= and stall= go with joint targets</source>
        <translation>line %1: lever=, ramp= and stall= go with joint targets</translation>
    </message>
    <message>
        <location line="+49" />
        <location line="+7" />
        <source>line %1: the model has no joint %2</source>
        <translation>line %1: the model has no joint %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>line %1: the profile "%2" gives joint %3 no lever of a serial console</source>
        <translation>line %1: the profile "%2" gives joint %3 no lever of a serial console</translation>
    </message>
    <message>
        <location line="+4" />
        <source>line %1: joint %2's drive is not enabled in this tutorial</source>
        <translation>line %1: joint %2's drive is not enabled in this tutorial</translation>
    </message>
</context>
<context>
    <name>TutorialSession</name>
    <message>
        <location filename="../trainer/training/session.cpp" line="+77" />
        <source>Goal done</source>
        <translation>Goal done</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Grasp</source>
        <translation>Grasp</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Missed grasp</source>
        <translation>Missed grasp</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Release</source>
        <translation>Release</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Load dropped</source>
        <translation>Load dropped</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hit</source>
        <translation>Hit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hard hit</source>
        <translation>Hard hit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Near miss</source>
        <translation>Near miss</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker's safety zone</source>
        <translation>Worker's safety zone</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker hit</source>
        <translation>Worker hit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overload</source>
        <translation>Overload</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Limit bang</source>
        <translation>Limit bang</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pump saturated</source>
        <translation>Pump saturated</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cavitation</source>
        <translation>Cavitation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time up</source>
        <translation>Time up</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Input ended</source>
        <translation>Input ended</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulation stopped</source>
        <translation>Simulation stopped</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Instructor</source>
        <translation>Instructor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stopped</source>
        <translation>Stopped</translation>
    </message>
    <message>
        <location line="+75" />
        <source>Goal done: %1</source>
        <translation>Goal done: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load is in the claws</source>
        <translation>The load is in the claws</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The claws closed %1 m away from the grip</source>
        <translation>The claws closed %1 m away from the grip</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load was released</source>
        <translation>The load was released</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The load was released out of place and fell</source>
        <translation>The load was released out of place and fell</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touched %1 at %2 m/s</source>
        <translation>Touched %1 at %2 m/s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hit %1 hard, at %2 m/s: the attempt ends</source>
        <translation>Hit %1 hard, at %2 m/s: the attempt ends</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Passed %1 m from %2</source>
        <translation>Passed %1 m from %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Entered the safety zone of %1 (%2 m)</source>
        <translation>Entered the safety zone of %1 (%2 m)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touched %1: the attempt ends</source>
        <translation>Touched %1: the attempt ends</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Relief valve of %1 opened (%2 kN)</source>
        <translation>Relief valve of %1 opened (%2 kN)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 hit its end stop at full speed</source>
        <translation>%1 hit its end stop at full speed</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The pump %1 could not give the %2 L/min the levers asked for: every function slowed</source>
        <translation>The pump %1 could not give the %2 L/min the levers asked for: every function slowed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 ran ahead of the oil: its cylinder cavitated</source>
        <translation>%1 ran ahead of the oil: its cylinder cavitated</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The time limit was reached</source>
        <translation>The time limit was reached</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The recorded input ended before the goals were done</source>
        <translation>The recorded input ended before the goals were done</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The simulation stopped: %1</source>
        <translation>The simulation stopped: %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Instructor %1 started the attempt</source>
        <translation>Instructor %1 started the attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 paused the attempt</source>
        <translation>Instructor %1 paused the attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 resumed the attempt</source>
        <translation>Instructor %1 resumed the attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 restarted the tutorial</source>
        <translation>Instructor %1 restarted the tutorial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1 stopped the attempt</source>
        <translation>Instructor %1 stopped the attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor %1: %2</source>
        <translation>Instructor %1: %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>The attempt was stopped</source>
        <translation>The attempt was stopped</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Path</source>
        <translation>Path</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Smoothness</source>
        <translation>Smoothness</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Safety</source>
        <translation>Safety</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Work faster: move several valves together once you are sure of the way.</source>
        <translation>Work faster: move several valves together once you are sure of the way.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Take a straighter way: plan the movement before you start, and avoid going back and forth.</source>
        <translation>Take a straighter way: plan the movement before you start, and avoid going back and forth.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Move the levers gently: open and close the valves gradually so the load does not jerk.</source>
        <translation>Move the levers gently: open and close the valves gradually so the load does not jerk.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep clear of the mill, the cart and the people, do not force the cylinders against their relief valves and do not run into the end stops.</source>
        <translation>Keep clear of the mill, the cart and the people, do not force the cylinders against their relief valves and do not run into the end stops.</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Nothing was done towards the goals: drive the machine towards the first one (the start screen names the keys and levers of each drive).</source>
        <translation>Nothing was done towards the goals: drive the machine towards the first one (the start screen names the keys and levers of each drive).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Complete every goal: the stage is passed only when all are done.</source>
        <translation>Complete every goal: the stage is passed only when all are done.</translation>
    </message>
    <message>
        <location line="-150" />
        <source>Fault injected</source>
        <translation>Fault injected</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fault cleared</source>
        <translation>Fault cleared</translation>
    </message>
    <message>
        <location filename="../trainer/training/faults.cpp" line="+40" />
        <source>Hose burst</source>
        <translation>Hose burst</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stuck valve</source>
        <translation>Stuck valve</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Worker walks in</source>
        <translation>Worker walks in</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Power cut</source>
        <translation>Power cut</translation>
    </message>
    <message>
        <location filename="../trainer/training/session.cpp" line="+41" />
        <source>Instructor: the hose of %1 was repaired</source>
        <translation>Instructor: the hose of %1 was repaired</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: a hose of %1 burst; the drive has no pressure</source>
        <translation>Instructor: a hose of %1 burst; the drive has no pressure</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: the valve of %1 was freed</source>
        <translation>Instructor: the valve of %1 was freed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: the valve of %1 stuck at %2 % of its opening</source>
        <translation>Instructor: the valve of %1 stuck at %2 % of its opening</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: %1 left the work area</source>
        <translation>Instructor: %1 left the work area</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: %1 walked into the work area</source>
        <translation>Instructor: %1 walked into the work area</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Instructor: the power is back</source>
        <translation>Instructor: the power is back</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Instructor: the power was cut; every valve closed</source>
        <translation>Instructor: the power was cut; every valve closed</translation>
    </message>
    <message>
        <location line="+767" />
        <source>There is no drive "%1": this machine has no hydraulic drives</source>
        <translation>There is no drive "%1": this machine has no hydraulic drives</translation>
    </message>
    <message>
        <location line="+1" />
        <source>There is no drive "%1" on this machine; its hydraulic drives are: %2</source>
        <translation>There is no drive "%1" on this machine; its hydraulic drives are: %2</translation>
    </message>
    <message>
        <location line="+54" />
        <source>The attempt has ended: no fault can be injected</source>
        <translation>The attempt has ended: no fault can be injected</translation>
    </message>
    <message>
        <location line="+21" />
        <source>A burst hose's damping and residual force must be zero or more</source>
        <translation>A burst hose's damping and residual force must be zero or more</translation>
    </message>
    <message>
        <location line="+5" />
        <source>A stuck valve's opening is a command from -1 to 1, not %1</source>
        <translation>A stuck valve's opening is a command from -1 to 1, not %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>This tutorial has no worker who could walk in (it has no WORKER)</source>
        <translation>This tutorial has no worker who could walk in (it has no WORKER)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>There is no worker %1 in this tutorial: its workers are numbered 0 to %2</source>
        <translation>There is no worker %1 in this tutorial: its workers are numbered 0 to %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Worker %1 has no graphics in the scene that could be moved</source>
        <translation>Worker %1 has no graphics in the scene that could be moved</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The place a worker walks to must be a finite position</source>
        <translation>The place a worker walks to must be a finite position</translation>
    </message>
    <message>
        <location line="+18" />
        <source>The attempt has ended: no fault can be cleared</source>
        <translation>The attempt has ended: no fault can be cleared</translation>
    </message>
    <message>
        <location line="+23" />
        <source>No hose of %1 has burst</source>
        <translation>No hose of %1 has burst</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The valve of %1 is not stuck</source>
        <translation>The valve of %1 is not stuck</translation>
    </message>
    <message>
        <location line="+2" />
        <source>No worker has walked in</source>
        <translation>No worker has walked in</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Worker %1 has not walked in</source>
        <translation>Worker %1 has not walked in</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The power has not been cut</source>
        <translation>The power has not been cut</translation>
    </message>
</context>
<context>
    <name>Tutorials</name>
    <message>
        <location filename="../trainer/training/tutorial.cpp" line="+53" />
        <source>%1 has no %2 text</source>
        <translation>%1 has no %2 text</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add %1 "…": every text is in Spanish and English</source>
        <translation>add %1 "…": every text is in Spanish and English</translation>
    </message>
    <message>
        <location line="+30" />
        <source>a tutorial file</source>
        <translation>a tutorial file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a tutorial is a short text file; check that this is one</source>
        <translation>a tutorial is a short text file; check that this is one</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the TITLE</source>
        <translation>the TITLE</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tutorial has no TITLE</source>
        <translation>the tutorial has no TITLE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add TITLE ES "…" EN "…"</source>
        <translation>add TITLE ES "…" EN "…"</translation>
    </message>
    <message>
        <location line="+2" />
        <source>this INTRO</source>
        <translation>this INTRO</translation>
    </message>
    <message>
        <location line="+3" />
        <source>goal '%1' has no NAME</source>
        <translation>goal '%1' has no NAME</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a NAME ES "…" EN "…" line after it: the HUD shows it</source>
        <translation>add a NAME ES "…" EN "…" line after it: the HUD shows it</translation>
    </message>
    <message>
        <location line="+2" />
        <source>goal '%1''s NAME</source>
        <translation>goal '%1''s NAME</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this HINT</source>
        <translation>this HINT</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this PART has no NAME</source>
        <translation>this PART has no NAME</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add a NAME ES "…" EN "…" line after it</source>
        <translation>add a NAME ES "…" EN "…" line after it</translation>
    </message>
    <message>
        <location line="+2" />
        <source>this PART's NAME</source>
        <translation>this PART's NAME</translation>
    </message>
    <message>
        <location line="+4" />
        <source>this WORKER's NAME</source>
        <translation>this WORKER's NAME</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the model '%1' cannot be used (errors above)</source>
        <translation>the model '%1' cannot be used (errors above)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the model, or check the path: it is relative to the tutorial's folder</source>
        <translation>fix the model, or check the path: it is relative to the tutorial's folder</translation>
    </message>
    <message>
        <location line="+14" />
        <source>the scene '%1' cannot be used (errors above)</source>
        <translation>the scene '%1' cannot be used (errors above)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>fix the scene, or check the path: it is relative to the tutorial's folder</source>
        <translation>fix the scene, or check the path: it is relative to the tutorial's folder</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the scene '%1' cannot be used with the model's CONTACT (errors above)</source>
        <translation>the scene '%1' cannot be used with the model's CONTACT (errors above)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>mark the scene's graphics that the model must not touch NOCONTACT</source>
        <translation>mark the scene's graphics that the model must not touch NOCONTACT</translation>
    </message>
    <message>
        <location line="+16" />
        <source>%1: the model has no moving body %2</source>
        <translation>%1: the model has no moving body %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a body id of '%1' (not the ground, 0)</source>
        <translation>use a body id of '%1' (not the ground, 0)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: the model has no joint %2 in its tree</source>
        <translation>%1: the model has no joint %2 in its tree</translation>
    </message>
    <message>
        <location line="+3" />
        <source>use a joint id (C) of '%1'</source>
        <translation>use a joint id (C) of '%1'</translation>
    </message>
    <message>
        <location line="+11" />
        <source>joint %1 has no drive</source>
        <translation>joint %1 has no drive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>DRIVES lists joints with a D statement in the model</source>
        <translation>DRIVES lists joints with a D statement in the model</translation>
    </message>
    <message>
        <location line="+12" />
        <source>joint %1's actuator cannot reach %2</source>
        <translation>joint %1's actuator cannot reach %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a length the joint's geometry allows</source>
        <translation>give a length the joint's geometry allows</translation>
    </message>
    <message>
        <location line="+5" />
        <source>joint %1's initial value %2 is beyond its limits</source>
        <translation>joint %1's initial value %2 is beyond its limits</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a value between its LL and UL</source>
        <translation>give a value between its LL and UL</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the load and the tool are the same body</source>
        <translation>the load and the tool are the same body</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the tool grips another body</source>
        <translation>the tool grips another body</translation>
    </message>
    <message>
        <location line="+3" />
        <source>GRIP has no CLAW</source>
        <translation>GRIP has no CLAW</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add CLAW joint CLOSE value OPEN value lines after it</source>
        <translation>add CLAW joint CLOSE value OPEN value lines after it</translation>
    </message>
    <message>
        <location line="+27" />
        <source>goal '%1' has no JOINT line</source>
        <translation>goal '%1' has no JOINT line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add JOINT id AT value TOL d lines after it</source>
        <translation>add JOINT id AT value TOL d lines after it</translation>
    </message>
    <message>
        <location line="+8" />
        <source>joint %1 cannot reach %2: beyond its limits</source>
        <translation>joint %1 cannot reach %2: beyond its limits</translation>
    </message>
    <message>
        <location line="+3" />
        <source>give a target between the joint's LL and UL</source>
        <translation>give a target between the joint's LL and UL</translation>
    </message>
    <message>
        <location line="+8" />
        <source>a GRASP goal needs a GRIP statement</source>
        <translation>a GRASP goal needs a GRIP statement</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+7" />
        <source>add GRIP LOAD … TOOL … (docs/training.md)</source>
        <translation>add GRIP LOAD … TOOL … (docs/training.md)</translation>
    </message>
    <message>
        <location line="-1" />
        <source>a PLACE goal needs a GRIP statement</source>
        <translation>a PLACE goal needs a GRIP statement</translation>
    </message>
    <message>
        <location line="+5" />
        <source>goal '%1' places the load before any GRASP goal</source>
        <translation>goal '%1' places the load before any GRASP goal</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put a GRASP goal before it</source>
        <translation>put a GRASP goal before it</translation>
    </message>
    <message>
        <location line="+13" />
        <source>HINT names goal '%1', which the tutorial does not have</source>
        <translation>HINT names goal '%1', which the tutorial does not have</translation>
    </message>
    <message>
        <location line="+1" />
        <source>use a GOAL's id</source>
        <translation>use a GOAL's id</translation>
    </message>
    <message>
        <location line="+23" />
        <source>WORKER needs a SCENE with the person's graphics</source>
        <translation>WORKER needs a SCENE with the person's graphics</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add SCENE "…"</source>
        <translation>add SCENE "…"</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the scene has no graphic G %1</source>
        <translation>the scene has no graphic G %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>use the G ids of the person in the scene file</source>
        <translation>use the G ids of the person in the scene file</translation>
    </message>
    <message>
        <location line="+10" />
        <source>PART SCENE needs a SCENE</source>
        <translation>PART SCENE needs a SCENE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add SCENE "…", or write PART MODEL for the model's graphics</source>
        <translation>add SCENE "…", or write PART MODEL for the model's graphics</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the scene has no ground graphic G %1</source>
        <translation>the scene has no ground graphic G %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the model has no ground graphic G %1</source>
        <translation>the model has no ground graphic G %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>use the G ids (on body 0) of the part</source>
        <translation>use the G ids (on body 0) of the part</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the station profile '%1' cannot be used: %2</source>
        <translation>the station profile '%1' cannot be used: %2</translation>
    </message>
    <message>
        <location line="+3" />
        <source>name one of the model's profiles or give a .json file relative to the tutorial</source>
        <translation>name one of the model's profiles or give a .json file relative to the tutorial</translation>
    </message>
    <message>
        <location line="+14" />
        <source>goal '%1' cannot be reached with the enabled drives: the nearest pose misses it by %2 m and %3°</source>
        <translation>goal '%1' cannot be reached with the enabled drives: the nearest pose misses it by %2 m and %3°</translation>
    </message>
    <message>
        <location line="+5" />
        <source>move the target within reach, enable more DRIVES or widen TOL/ANGTOL</source>
        <translation>move the target within reach, enable more DRIVES or widen TOL/ANGTOL</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the demonstration cannot be used: %1</source>
        <translation>the demonstration cannot be used: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>record it again (Train ▸ Record demonstration) or fix the path</source>
        <translation>record it again (Train ▸ Record demonstration) or fix the path</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the demonstration's camera path cannot be used: %1</source>
        <translation>the demonstration's camera path cannot be used: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>record the demonstration again, or remove CAMERA: the viewer's own camera is used</source>
        <translation>record the demonstration again, or remove CAMERA: the viewer's own camera is used</translation>
    </message>
    <message>
        <location filename="../trainer/training/tutorial_parser.cpp" line="+71" />
        <source>expected %1 %2</source>
        <translation>expected %1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write %1 followed by its value</source>
        <translation>write %1 followed by its value</translation>
    </message>
    <message>
        <location line="+7" />
        <source>expected %1, found the end of the line</source>
        <translation>expected %1, found the end of the line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>expected %1, found '%2'</source>
        <translation>expected %1, found '%2'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number such as 0.5</source>
        <translation>write a number such as 0.5</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: '%2' is not a finite number</source>
        <translation>%1: '%2' is not a finite number</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: '%2' is too large for a number</source>
        <translation>%1: '%2' is too large for a number</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write a number within ±1e308; check the units</source>
        <translation>write a number within ±1e308; check the units</translation>
    </message>
    <message>
        <location line="+6" />
        <source>decimals take a point, not a comma: %1</source>
        <translation>decimals take a point, not a comma: %1</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 must be a whole number</source>
        <translation>%1 must be a whole number</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write it without decimals</source>
        <translation>write it without decimals</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1 (three numbers: x y z)</source>
        <translation>%1 (three numbers: x y z)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1 is the zero vector</source>
        <translation>%1 is the zero vector</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give a direction, e.g. 0 0 1</source>
        <translation>give a direction, e.g. 0 0 1</translation>
    </message>
    <message>
        <location line="+9" />
        <source>expected %1 in double quotes</source>
        <translation>expected %1 in double quotes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write it as "…"</source>
        <translation>write it as "…"</translation>
    </message>
    <message>
        <location line="+26" />
        <source>the text is given twice in %1</source>
        <translation>the text is given twice in %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>keep one</source>
        <translation>keep one</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the %1 text</source>
        <translation>the %1 text</translation>
    </message>
    <message>
        <location line="+3" />
        <source>expected the text in each language: ES "…" EN "…"</source>
        <translation>expected the text in each language: ES "…" EN "…"</translation>
    </message>
    <message>
        <location line="+1" />
        <source>every text a person reads is written in Spanish and English</source>
        <translation>every text a person reads is written in Spanish and English</translation>
    </message>
    <message>
        <location line="+6" />
        <source>unexpected '%1' here</source>
        <translation>unexpected '%1' here</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove it, or check the statement's keywords in docs/training.md</source>
        <translation>remove it, or check the statement's keywords in docs/training.md</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 must not be negative</source>
        <translation>%1 must not be negative</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 must be greater than 0</source>
        <translation>%1 must be greater than 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give a positive value</source>
        <translation>give a positive value</translation>
    </message>
    <message>
        <location line="+35" />
        <source>%1 is given twice</source>
        <translation>%1 is given twice</translation>
    </message>
    <message>
        <location line="+1" />
        <source>keep one %1 statement</source>
        <translation>keep one %1 statement</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 belongs to a GOAL and must follow it</source>
        <translation>%1 belongs to a GOAL and must follow it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it on the lines after its GOAL statement</source>
        <translation>put it on the lines after its GOAL statement</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the tutorial's id, e.g. T0</source>
        <translation>the tutorial's id, e.g. T0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the level</source>
        <translation>the level</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the station profile's name or file</source>
        <translation>the station profile's name or file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the file's path</source>
        <translation>the file's path</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the demonstration's input log</source>
        <translation>the demonstration's input log</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the demonstration's camera path</source>
        <translation>the demonstration's camera path</translation>
    </message>
    <message>
        <location line="+4" />
        <source>a drive's joint id</source>
        <translation>a drive's joint id</translation>
    </message>
    <message>
        <location line="+2" />
        <source>DRIVES lists no drive</source>
        <translation>DRIVES lists no drive</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write the joint ids of the drives the operator may use</source>
        <translation>write the joint ids of the drives the operator may use</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+175" />
        <source>the joint id</source>
        <translation>the joint id</translation>
    </message>
    <message>
        <location line="-174" />
        <source>the joint's initial value</source>
        <translation>the joint's initial value</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(TIME LIMIT seconds PAR seconds)</source>
        <translation>(TIME LIMIT seconds PAR seconds)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time limit [s]</source>
        <translation>the time limit [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time limit</source>
        <translation>the time limit</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the time that earns every time point)</source>
        <translation>(the time that earns every time point)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the par time [s]</source>
        <translation>the par time [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the par time</source>
        <translation>the par time</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the par time is longer than the time limit</source>
        <translation>the par time is longer than the time limit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>make PAR at most LIMIT</source>
        <translation>make PAR at most LIMIT</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the pass mark (0–100)</source>
        <translation>the pass mark (0–100)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the pass mark must be between 0 and 100</source>
        <translation>the pass mark must be between 0 and 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>e.g. PASS 60</source>
        <translation>e.g. PASS 60</translation>
    </message>
    <message>
        <location line="+6" />
        <source>(WEIGHTS TIME a PATH b SMOOTH c SAFETY d)</source>
        <translation>(WEIGHTS TIME a PATH b SMOOTH c SAFETY d)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time weight</source>
        <translation>the time weight</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the path weight</source>
        <translation>the path weight</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the smoothness weight</source>
        <translation>the smoothness weight</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the safety weight</source>
        <translation>the safety weight</translation>
    </message>
    <message>
        <location line="+3" />
        <source>a weight is negative</source>
        <translation>a weight is negative</translation>
    </message>
    <message>
        <location line="+1" />
        <source>weights are points, 0 or more</source>
        <translation>weights are points, 0 or more</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the reference RMS jerk [m/s³]</source>
        <translation>the reference RMS jerk [m/s³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the reference jerk</source>
        <translation>the reference jerk</translation>
    </message>
    <message>
        <location line="+3" />
        <source>(TRACK BODY id POINT x y z)</source>
        <translation>(TRACK BODY id POINT x y z)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+69" />
        <source>the body id</source>
        <translation>the body id</translation>
    </message>
    <message>
        <location line="-67" />
        <location line="+69" />
        <source>the point on the body</source>
        <translation>the point on the body</translation>
    </message>
    <message>
        <location line="-62" />
        <source>(GRIP LOAD body AT x y z TOOL body AT x y z TOL d ANGTOL a)</source>
        <translation>(GRIP LOAD body AT x y z TOOL body AT x y z TOL d ANGTOL a)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load's body id</source>
        <translation>the load's body id</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the grip point on the load, in its frame)</source>
        <translation>(the grip point on the load, in its frame)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip point on the load</source>
        <translation>the grip point on the load</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the body that grips)</source>
        <translation>(the body that grips)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the tool's body id</source>
        <translation>the tool's body id</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(the grip point on the tool, in its frame)</source>
        <translation>(the grip point on the tool, in its frame)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip point on the tool</source>
        <translation>the grip point on the tool</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(how close the two grip points must be [m])</source>
        <translation>(how close the two grip points must be [m])</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip's position tolerance [m]</source>
        <translation>the grip's position tolerance [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the grip's tolerance</source>
        <translation>the grip's tolerance</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(how far the load's attitude may be from the tool's)</source>
        <translation>(how far the load's attitude may be from the tool's)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+1" />
        <source>the grip's angle tolerance</source>
        <translation>the grip's angle tolerance</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the load's rotation axis in the tool frame</source>
        <translation>the load's rotation axis in the tool frame</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the rotation angle</source>
        <translation>the rotation angle</translation>
    </message>
    <message>
        <location line="+6" />
        <source>CLAW belongs to GRIP and must follow it</source>
        <translation>CLAW belongs to GRIP and must follow it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put the CLAW lines after the GRIP statement</source>
        <translation>put the CLAW lines after the GRIP statement</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the claw's joint id</source>
        <translation>the claw's joint id</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(CLAW joint CLOSE value OPEN value)</source>
        <translation>(CLAW joint CLOSE value OPEN value)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the value past which the claw is closed</source>
        <translation>the value past which the claw is closed</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the value past which the claw is open</source>
        <translation>the value past which the claw is open</translation>
    </message>
    <message>
        <location line="+2" />
        <source>CLOSE and OPEN are the same value</source>
        <translation>CLOSE and OPEN are the same value</translation>
    </message>
    <message>
        <location line="+1" />
        <source>OPEN is nearer the claw's open end than CLOSE</source>
        <translation>OPEN is nearer the claw's open end than CLOSE</translation>
    </message>
    <message>
        <location line="+7" />
        <source>FINGERS belongs to GRIP and must follow it</source>
        <translation>FINGERS belongs to GRIP and must follow it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it after the GRIP statement</source>
        <translation>put it after the GRIP statement</translation>
    </message>
    <message>
        <location line="+2" />
        <source>a body id</source>
        <translation>a body id</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+97" />
        <source>the goal's id</source>
        <translation>the goal's id</translation>
    </message>
    <message>
        <location line="-94" />
        <source>goal '%1' is defined twice</source>
        <translation>goal '%1' is defined twice</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give every goal its own id</source>
        <translation>give every goal its own id</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(GOAL id REACH BODY b POINT x y z AT x y z TOL d)</source>
        <translation>(GOAL id REACH BODY b POINT x y z AT x y z TOL d)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the point on the body, in its frame)</source>
        <translation>(the point on the body, in its frame)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the target in the world)</source>
        <translation>(the target in the world)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the target</source>
        <translation>the target</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+12" />
        <source>(how near [m])</source>
        <translation>(how near [m])</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+12" />
        <source>the tolerance [m]</source>
        <translation>the tolerance [m]</translation>
    </message>
    <message>
        <location line="-11" />
        <location line="+12" />
        <location line="+39" />
        <location line="+1" />
        <source>the tolerance</source>
        <translation>the tolerance</translation>
    </message>
    <message>
        <location line="-45" />
        <source>(GOAL id PLACE AT x y z TOL d: the load's centre of mass)</source>
        <translation>(GOAL id PLACE AT x y z TOL d: the load's centre of mass)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the load's target position</source>
        <translation>the load's target position</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the seat zone [m]</source>
        <translation>the seat zone [m]</translation>
    </message>
    <message>
        <location line="+4" />
        <source>expected the kind of goal: REACH, JOINT, GRASP or PLACE</source>
        <translation>expected the kind of goal: REACH, JOINT, GRASP or PLACE</translation>
    </message>
    <message>
        <location line="+1" />
        <source>e.g. GOAL g1 REACH BODY 6 POINT 0 0 0 AT 1 2 0.5 TOL 0.1</source>
        <translation>e.g. GOAL g1 REACH BODY 6 POINT 0 0 0 AT 1 2 0.5 TOL 0.1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the direction on the body</source>
        <translation>the direction on the body</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(ALIGN x y z WITH x y z ANGTOL a)</source>
        <translation>(ALIGN x y z WITH x y z ANGTOL a)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the direction in the world</source>
        <translation>the direction in the world</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(the angle tolerance)</source>
        <translation>(the angle tolerance)</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+1" />
        <source>the angle tolerance</source>
        <translation>the angle tolerance</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ALIGN applies to REACH and PLACE goals</source>
        <translation>ALIGN applies to REACH and PLACE goals</translation>
    </message>
    <message>
        <location line="+1" />
        <source>remove it</source>
        <translation>remove it</translation>
    </message>
    <message>
        <location line="+9" />
        <source>(JOINT id AT value TOL d)</source>
        <translation>(JOINT id AT value TOL d)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the joint's target</source>
        <translation>the joint's target</translation>
    </message>
    <message>
        <location line="+6" />
        <source>JOINT lines belong to a JOINT goal</source>
        <translation>JOINT lines belong to a JOINT goal</translation>
    </message>
    <message>
        <location line="+1" />
        <source>write GOAL id JOINT, then the JOINT lines</source>
        <translation>write GOAL id JOINT, then the JOINT lines</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the dwell time [s]</source>
        <translation>the dwell time [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the dwell time</source>
        <translation>the dwell time</translation>
    </message>
    <message>
        <location line="+11" />
        <source>NAME belongs to a GOAL, a WORKER or a PART and must follow it</source>
        <translation>NAME belongs to a GOAL, a WORKER or a PART and must follow it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>put it on the line after its GOAL, WORKER or PART</source>
        <translation>put it on the line after its GOAL, WORKER or PART</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the time on the goal before the hint shows [s]</source>
        <translation>the time on the goal before the hint shows [s]</translation>
    </message>
    <message>
        <location line="+8" />
        <source>(WORKER G id id … ZONE d PENALTY p: the scene's graphics of the person)</source>
        <translation>(WORKER G id id … ZONE d PENALTY p: the scene's graphics of the person)</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+20" />
        <source>a graphic id</source>
        <translation>a graphic id</translation>
    </message>
    <message>
        <location line="-18" />
        <source>WORKER lists no graphic</source>
        <translation>WORKER lists no graphic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give the scene's G ids of the person</source>
        <translation>give the scene's G ids of the person</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the safety zone [m]</source>
        <translation>the safety zone [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the safety zone</source>
        <translation>the safety zone</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the penalty [points]</source>
        <translation>the penalty [points]</translation>
    </message>
    <message>
        <location line="+8" />
        <source>(PART [SCENE|MODEL] G id id …, then a NAME line)</source>
        <translation>(PART [SCENE|MODEL] G id id …, then a NAME line)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>PART lists no graphic</source>
        <translation>PART lists no graphic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give the G ids of the part</source>
        <translation>give the G ids of the part</translation>
    </message>
    <message>
        <location line="+6" />
        <source>(AVOID SCENE PENALTY p NEAR d HARD v)</source>
        <translation>(AVOID SCENE PENALTY p NEAR d HARD v)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the penalty per hit [points]</source>
        <translation>the penalty per hit [points]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the near-miss distance [m]</source>
        <translation>the near-miss distance [m]</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the speed of a hard hit [m/s]</source>
        <translation>the speed of a hard hit [m/s]</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(OVERLOAD PENALTY p)</source>
        <translation>(OVERLOAD PENALTY p)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty per overload [points]</source>
        <translation>the penalty per overload [points]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>(LIMITS PENALTY p SPEED f)</source>
        <translation>(LIMITS PENALTY p SPEED f)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty per limit bang [points]</source>
        <translation>the penalty per limit bang [points]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the fraction of the drive's speed</source>
        <translation>the fraction of the drive's speed</translation>
    </message>
    <message>
        <location line="+5" />
        <source>(DROP PENALTY p)</source>
        <translation>(DROP PENALTY p)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the penalty for releasing the load out of place [points]</source>
        <translation>the penalty for releasing the load out of place [points]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>unknown statement '%1'</source>
        <translation>unknown statement '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a tutorial's statements are TUTORIAL, TITLE, INTRO, MODEL, SCENE, PROFILE, DEMO, DRIVES, SET, TIME, PASS, WEIGHTS, JERK, TRACK, GRIP, CLAW, FINGERS, GOAL (with ALIGN, JOINT, DWELL, NAME), HINT, WORKER, PART, AVOID, OVERLOAD, LIMITS, DROP</source>
        <translation>a tutorial's statements are TUTORIAL, TITLE, INTRO, MODEL, SCENE, PROFILE, DEMO, DRIVES, SET, TIME, PASS, WEIGHTS, JERK, TRACK, GRIP, CLAW, FINGERS, GOAL (with ALIGN, JOINT, DWELL, NAME), HINT, WORKER, PART, AVOID, OVERLOAD, LIMITS, DROP</translation>
    </message>
    <message>
        <location line="+13" />
        <source>the file has no TUTORIAL statement</source>
        <translation>the file has no TUTORIAL statement</translation>
    </message>
    <message>
        <location line="+1" />
        <source>start the file with TUTORIAL &lt;id&gt;, e.g. TUTORIAL T0</source>
        <translation>start the file with TUTORIAL &lt;id&gt;, e.g. TUTORIAL T0</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the tutorial names no MODEL</source>
        <translation>the tutorial names no MODEL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add MODEL "path/to/model.pad"</source>
        <translation>add MODEL "path/to/model.pad"</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the tutorial has no GOAL</source>
        <translation>the tutorial has no GOAL</translation>
    </message>
    <message>
        <location line="+1" />
        <source>add at least one GOAL</source>
        <translation>add at least one GOAL</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the weights add up to %1, not 100</source>
        <translation>the weights add up to %1, not 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the score is out of 100: make TIME + PATH + SMOOTH + SAFETY = 100</source>
        <translation>the score is out of 100: make TIME + PATH + SMOOTH + SAFETY = 100</translation>
    </message>
    <message>
        <location filename="../ide/cli/tutorial.cpp" line="+246" />
        <source>an autopilot path</source>
        <translation>an autopilot path</translation>
    </message>
    <message>
        <location line="+1" />
        <source>an autopilot path is a short text file of waypoints; check that this is one</source>
        <translation>an autopilot path is a short text file of waypoints; check that this is one</translation>
    </message>
    <message>
        <location filename="../trainer/input/input_log.cpp" line="+62" />
        <source>an input log</source>
        <translation>an input log</translation>
    </message>
    <message>
        <location line="+1" />
        <source>an input log is a text file that padrob writes while a run is recorded; check that this is one</source>
        <translation>an input log is a text file that padrob writes while a run is recorded; check that this is one</translation>
    </message>
    <message>
        <location filename="../trainer/station/profile_store.cpp" line="+29" />
        <source>a station profile</source>
        <translation>a station profile</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a station profile is a short JSON file; check that this is one</source>
        <translation>a station profile is a short JSON file; check that this is one</translation>
    </message>
    <message>
        <location filename="../trainer/training/attempt_log.cpp" line="-54" />
        <source>a pending attempt</source>
        <translation>a pending attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a pending attempt is a JSON file that padrob writes; check that this is one</source>
        <translation>a pending attempt is a JSON file that padrob writes; check that this is one</translation>
    </message>
    <message>
        <location filename="../trainer/training/camera_path.cpp" line="-36" />
        <source>a camera path</source>
        <translation>a camera path</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a camera path is a text file that padrob writes while a demonstration is recorded; check that this is one</source>
        <translation>a camera path is a text file that padrob writes while a demonstration is recorded; check that this is one</translation>
    </message>
</context>
<context>
    <name>padrob</name>
    <message>
        <location filename="../ide/cli/bench.cpp" line="+236" />
        <source>the simulation failed: %1</source>
        <translation>the simulation failed: %1</translation>
    </message>
    <message>
        <location line="+144" />
        <source>not compared with --integrator adaptive (MuJoCo is timed with RK4 at dt)</source>
        <translation>not compared with --integrator adaptive (MuJoCo is timed with RK4 at dt)</translation>
    </message>
    <message>
        <location line="+10" />
        <source>no timings</source>
        <translation>no timings</translation>
    </message>
    <message>
        <location line="+61" />
        <source>generated model of %1 bodies does not compile</source>
        <translation>generated model of %1 bodies does not compile</translation>
    </message>
    <message>
        <location line="+13" />
        <source>tree of %1 bodies: %2</source>
        <translation>tree of %1 bodies: %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain of %1 bodies: %2</source>
        <translation>chain of %1 bodies: %2</translation>
    </message>
    <message>
        <location line="+174" />
        <source>machine: %1, %2 cores</source>
        <translation>machine: %1, %2 cores</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>each figure: the median of %n run(s) after a warm-up run, and the fastest – slowest run</source>
        <translation>
            <numerusform>each figure: the median of %n run after a warm-up run, and the fastest – slowest run</numerusform>
            <numerusform>each figure: the median of %n runs after a warm-up run, and the fastest – slowest run</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6" />
        <source>model: %1 (bodies: %2, drives: %3, loop closures: %4)</source>
        <translation>model: %1 (bodies: %2, drives: %3, loop closures: %4)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>scene: %1; CONTACT added (the model has none): MU 0.5, E 0</source>
        <translation>scene: %1; CONTACT added (the model has none): MU 0.5, E 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>scene: %1; the model's CONTACT</source>
        <translation>scene: %1; the model's CONTACT</translation>
    </message>
    <message>
        <location line="+4" />
        <source>steps: %1 of dt = %2 ms, %3</source>
        <translation>steps: %1 of dt = %2 ms, %3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>adaptive integrator (Dormand–Prince 5(4), rtol 1e-8)</source>
        <translation>adaptive integrator (Dormand–Prince 5(4), rtol 1e-8)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <location line="+2" />
        <source>[µs]</source>
        <translation>[µs]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>median</source>
        <translation>median</translation>
    </message>
    <message>
        <location line="+1" />
        <source>min – max</source>
        <translation>min – max</translation>
    </message>
    <message>
        <location line="+1" />
        <source>forward dynamics, per evaluation</source>
        <translation>forward dynamics, per evaluation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 evaluations/s</source>
        <translation>%1 evaluations/s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>realtime factor %1 (%2 – %3)</source>
        <translation>realtime factor %1 (%2 – %3)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>adaptive, per simulated ms</source>
        <translation>adaptive, per simulated ms</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RK4 step</source>
        <translation>RK4 step</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 steps/s, %2</source>
        <translation>%1 steps/s, %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RK4 step, commands held</source>
        <translation>RK4 step, commands held</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no restart after a new command</source>
        <translation>no restart after a new command</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RK4 step, passive, no limits</source>
        <translation>RK4 step, passive, no limits</translation>
    </message>
    <message>
        <location line="+0" />
        <source>no drives, no events</source>
        <translation>no drives, no events</translation>
    </message>
    <message>
        <location line="+3" />
        <source>contact phase, per RK4 step</source>
        <translation>contact phase, per RK4 step</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 contact points at a step's end (mean)</source>
        <translation>%1 contact points at a step's end (mean)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>reference N–E system, per solve</source>
        <translation>reference N–E system, per solve</translation>
    </message>
    <message>
        <location line="+1" />
        <source>×%1 Padrob's forward dynamics</source>
        <translation>×%1 Padrob's forward dynamics</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reference RK4 step</source>
        <translation>reference RK4 step</translation>
    </message>
    <message>
        <location line="+2" />
        <source>×%1 Padrob's RK4 step</source>
        <translation>×%1 Padrob's RK4 step</translation>
    </message>
    <message>
        <location line="+3" />
        <source>MuJoCo RK4 step (passive, no limits)</source>
        <translation>MuJoCo RK4 step (passive, no limits)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1 (passive %2)</source>
        <translation>Padrob / MuJoCo %1 (passive %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MuJoCo forward (mj_forward)</source>
        <translation>MuJoCo forward (mj_forward)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1</source>
        <translation>Padrob / MuJoCo %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>MuJoCo RK4 step, geoms and contacts</source>
        <translation>MuJoCo RK4 step, geoms and contacts</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob / MuJoCo %1 (%2 geoms, %3 contacts)</source>
        <translation>Padrob / MuJoCo %1 (%2 geoms, %3 contacts)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Steps: every drive commanded by a sine (amplitude 0.8, 0.5 Hz, phases spread) set before every
step (held: set once), limits and relief valves watched as events, the joint reactions computed
at every step's end. Events in one run: %1.</source>
        <translation>Steps: every drive commanded by a sine (amplitude 0.8, 0.5 Hz, phases spread) set before every
step (held: set once), limits and relief valves watched as events, the joint reactions computed
at every step's end. Events in one run: %1.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Reference: the thesis's Newton–Euler system A·X = B (eq. 2.8–2.11), dense LU, %1 solves
and %2 RK4 steps per run, modes and commands held, no events; its θ̈ differs from Padrob's
by %3 (relative).</source>
        <translation>Reference: the thesis's Newton–Euler system A·X = B (eq. 2.8–2.11), dense LU, %1 solves
and %2 RK4 steps per run, modes and commands held, no events; its θ̈ differs from Padrob's
by %3 (relative).</translation>
    </message>
    <message>
        <location line="+9" />
        <source>MuJoCo: the same trajectory within %1 m over %2 s.</source>
        <translation>MuJoCo: the same trajectory within %1 m over %2 s.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MuJoCo: the same trajectory within %1 m over %2 s; adjusted for MuJoCo:</source>
        <translation>MuJoCo: the same trajectory within %1 m over %2 s; adjusted for MuJoCo:</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Allocations in the step loop: not counted here (tests/alloc counts them).</source>
        <translation>Allocations in the step loop: not counted here (tests/alloc counts them).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>scaling: µs per RK4 step (median) of generated models: drives on every 3rd joint,
limits on all; commands held, or set every step</source>
        <translation>scaling: µs per RK4 step (median) of generated models: drives on every 3rd joint,
limits on all; commands held, or set every step</translation>
    </message>
    <message>
        <location line="+4" />
        <source>bodies</source>
        <translation>bodies</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain, held</source>
        <translation>chain, held</translation>
    </message>
    <message>
        <location line="+0" />
        <source>chain, commanded</source>
        <translation>chain, commanded</translation>
    </message>
    <message>
        <location line="+1" />
        <source>tree, held</source>
        <translation>tree, held</translation>
    </message>
    <message>
        <location line="+0" />
        <source>tree, commanded</source>
        <translation>tree, commanded</translation>
    </message>
    <message>
        <location line="+8" />
        <source>  p: time ∝ n^p by least squares on log–log (p ≈ 1 is linear)</source>
        <translation>  p: time ∝ n^p by least squares on log–log (p ≈ 1 is linear)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Usage: padrob bench MODEL [--scene FILE] [OPTIONS]
       padrob bench --scaling [OPTIONS]

Times the solver on a model: forward dynamics, RK4 steps with drives, limits and
joint reactions, the real-time factor, and the thesis's reference Newton–Euler
system A·X = B; with MuJoCo built in, MuJoCo on the same tree side by side.
Each figure is the median of R runs after one warm-up run, with the fastest and
slowest run (the machine is noisy); times in µs per evaluation or per step.

  --steps N             steps per timed run (default 5000); the forward dynamics
                        are timed over N evaluations, the reference over
                        min(N, 1000) solves and min(N, 250) steps
  --runs R              timed runs per figure (default 5)
  --dt H                step [s] (default 0.001)
  --integrator M        rk4 (default) or adaptive (Dormand–Prince 5(4), rtol 1e-8:
                        time per simulated millisecond)
  --json                print one JSON object (format "padrob-bench", version 1)
  --scaling             also time generated chains and binary trees of 10, 30, 100,
                        300 and 1000 bodies and fit time ∝ n^p (MODEL may then be
                        left out)
  --no-mujoco           skip the comparison with MuJoCo
  --scene FILE          run the model in a scene (its ground graphics) with contacts:
                        the model's CONTACT, or CONTACT (MU 0.5, E 0) added when it
                        has none; also times the contact phase per step (contact_us)
                        and MuJoCo on the export with the geoms (ratio_vs_mujoco)

The RK4 steps command every drive with a slow sine, set before every step (so
valves open and close and every step restarts the integrator, as at the station),
watch limits and relief valves, and compute the joint reactions at every
step's end; they are also timed with the commands held, and passive without
limits. The real-time factor is dt / step time.

Exit status: 0 success; 1 the model has errors or a simulation failed;
2 usage error or unreadable model.
</source>
        <translation>Usage: padrob bench MODEL [--scene FILE] [OPTIONS]
       padrob bench --scaling [OPTIONS]

Times the solver on a model: forward dynamics, RK4 steps with drives, limits and
joint reactions, the real-time factor, and the thesis's reference Newton–Euler
system A·X = B; with MuJoCo built in, MuJoCo on the same tree side by side.
Each figure is the median of R runs after one warm-up run, with the fastest and
slowest run (the machine is noisy); times in µs per evaluation or per step.

  --steps N             steps per timed run (default 5000); the forward dynamics
                        are timed over N evaluations, the reference over
                        min(N, 1000) solves and min(N, 250) steps
  --runs R              timed runs per figure (default 5)
  --dt H                step [s] (default 0.001)
  --integrator M        rk4 (default) or adaptive (Dormand–Prince 5(4), rtol 1e-8:
                        time per simulated millisecond)
  --json                print one JSON object (format "padrob-bench", version 1)
  --scaling             also time generated chains and binary trees of 10, 30, 100,
                        300 and 1000 bodies and fit time ∝ n^p (MODEL may then be
                        left out)
  --no-mujoco           skip the comparison with MuJoCo
  --scene FILE          run the model in a scene (its ground graphics) with contacts:
                        the model's CONTACT, or CONTACT (MU 0.5, E 0) added when it
                        has none; also times the contact phase per step (contact_us)
                        and MuJoCo on the export with the geoms (ratio_vs_mujoco)

The RK4 steps command every drive with a slow sine, set before every step (so
valves open and close and every step restarts the integrator, as at the station),
watch limits and relief valves, and compute the joint reactions at every
step's end; they are also timed with the commands held, and passive without
limits. The real-time factor is dt / step time.

Exit status: 0 success; 1 the model has errors or a simulation failed;
2 usage error or unreadable model.
</translation>
    </message>
    <message>
        <location line="+49" />
        <location line="+5" />
        <location filename="../ide/cli/centre.cpp" line="+90" />
        <location line="+6" />
        <location line="+2" />
        <location line="+3" />
        <location line="+3" />
        <location line="+565" />
        <location line="+51" />
        <location filename="../ide/cli/export.cpp" line="+92" />
        <location filename="../ide/cli/simulate.cpp" line="+243" />
        <location filename="../ide/cli/tutorial.cpp" line="-58" />
        <source>%1 needs a value</source>
        <translation>%1 needs a value</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 must be a whole number from 1 to %2, not '%3'</source>
        <translation>%1 must be a whole number from 1 to %2, not '%3'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>--dt must be a number of seconds above 0 and at most 1, not '%1'</source>
        <translation>--dt must be a number of seconds above 0 and at most 1, not '%1'</translation>
    </message>
    <message>
        <location line="+6" />
        <location filename="../ide/cli/simulate.cpp" line="+19" />
        <source>--integrator must be rk4 or adaptive, not '%1'</source>
        <translation>--integrator must be rk4 or adaptive, not '%1'</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../ide/cli/centre.cpp" line="-488" />
        <location line="+275" />
        <location line="+165" />
        <location line="+51" />
        <location line="+51" />
        <location filename="../ide/cli/export.cpp" line="+15" />
        <location filename="../ide/cli/inertia.cpp" line="+196" />
        <location filename="../ide/cli/main.cpp" line="+138" />
        <location line="+26" />
        <location filename="../ide/cli/simulate.cpp" line="+25" />
        <location filename="../ide/cli/tutorial.cpp" line="+8" />
        <source>unknown option '%1'</source>
        <translation>unknown option '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <location filename="../ide/cli/export.cpp" line="+1" />
        <location filename="../ide/cli/inertia.cpp" line="+4" />
        <location filename="../ide/cli/main.cpp" line="+4" />
        <location filename="../ide/cli/simulate.cpp" line="+1" />
        <source>give one model</source>
        <translation>give one model</translation>
    </message>
    <message>
        <location line="+3" />
        <location filename="../ide/cli/export.cpp" line="+4" />
        <location filename="../ide/cli/inertia.cpp" line="-1" />
        <location filename="../ide/cli/main.cpp" line="-27" />
        <location line="+26" />
        <location filename="../ide/cli/simulate.cpp" line="+3" />
        <source>no model given</source>
        <translation>no model given</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--scene needs a model</source>
        <translation>--scene needs a model</translation>
    </message>
    <message>
        <location line="+27" />
        <source>%1: the model has no moving body: nothing to time</source>
        <translation>%1: the model has no moving body: nothing to time</translation>
    </message>
    <message>
        <location line="+17" />
        <source>MuJoCo: %1</source>
        <translation>MuJoCo: %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>scaling: %1</source>
        <translation>scaling: %1</translation>
    </message>
    <message>
        <location filename="../ide/cli/cli_io.cpp" line="+26" />
        <source>Try 'padrob %1 --help'.</source>
        <translation>Try 'padrob %1 --help'.</translation>
    </message>
    <message>
        <location line="+92" />
        <source>the values given on the command line do not fit the model:</source>
        <translation>the values given on the command line do not fit the model:</translation>
    </message>
    <message>
        <location filename="../ide/cli/export.cpp" line="-65" />
        <source>Usage: padrob export --mjcf MODEL [--scene FILE] [--out FILE] [--dt H] [--check]

Writes a model without closed loops as MuJoCo's MJCF (XML). The bodies are posed
with every joint at 0, so MuJoCo's qpos of each joint is Padrob's coordinate
(the angle for T 0 and T 1 joints: a T 1 joint's length is not a coordinate in
MuJoCo; the displacement for T 2); the keyframe "initial" holds the model's
initial state. MuJoCo gets a passive model: drives, relief valves, limit
impulses and applied forces are not exported (the file's header says so). With
CONTACT the graphics become geoms (a TUBE a ring of boxes; CONE, PRISM and MESH
their convex hulls; NOCONTACT ones visual only) and contacts are on, with MuJoCo's
law set to approximate Padrob's; without CONTACT there are no geoms and contacts
are off. Bodies MuJoCo would refuse (massless, or an inertia breaking I1 + I2 &gt;= I3)
get the nearest values it accepts, with the true ones in a comment there.

  --mjcf        the format (required; the only one)
  --out FILE    write the MJCF there (default: standard output); the file is
                replaced whole or not at all
  --dt H        the time step written in &lt;option&gt; [s] (default 0.001)
  --scene FILE  with CONTACT: the scene's ground graphics (e.g. a mill) as world
                geoms, and the solids overlapping them at the start excluded
  --check       load the MJCF into MuJoCo (when padrob was built with it), put
                the true masses and inertias in, and check that MuJoCo and Padrob
                follow the same trajectory for 0.2 s (RK4 at --dt, every joint
                passive, no limits, the centres of mass within 1e-6 m); the
                result goes to standard error

Exit status: 0 success; 1 the model has errors, has closed loops, or MuJoCo
disagrees (--check); 2 usage error, unreadable model, or --check in a padrob
built without MuJoCo. On failure nothing is written.
</source>
        <translation>Usage: padrob export --mjcf MODEL [--scene FILE] [--out FILE] [--dt H] [--check]

Writes a model without closed loops as MuJoCo's MJCF (XML). The bodies are posed
with every joint at 0, so MuJoCo's qpos of each joint is Padrob's coordinate
(the angle for T 0 and T 1 joints: a T 1 joint's length is not a coordinate in
MuJoCo; the displacement for T 2); the keyframe "initial" holds the model's
initial state. MuJoCo gets a passive model: drives, relief valves, limit
impulses and applied forces are not exported (the file's header says so). With
CONTACT the graphics become geoms (a TUBE a ring of boxes; CONE, PRISM and MESH
their convex hulls; NOCONTACT ones visual only) and contacts are on, with MuJoCo's
law set to approximate Padrob's; without CONTACT there are no geoms and contacts
are off. Bodies MuJoCo would refuse (massless, or an inertia breaking I1 + I2 &gt;= I3)
get the nearest values it accepts, with the true ones in a comment there.

  --mjcf        the format (required; the only one)
  --out FILE    write the MJCF there (default: standard output); the file is
                replaced whole or not at all
  --dt H        the time step written in &lt;option&gt; [s] (default 0.001)
  --scene FILE  with CONTACT: the scene's ground graphics (e.g. a mill) as world
                geoms, and the solids overlapping them at the start excluded
  --check       load the MJCF into MuJoCo (when padrob was built with it), put
                the true masses and inertias in, and check that MuJoCo and Padrob
                follow the same trajectory for 0.2 s (RK4 at --dt, every joint
                passive, no limits, the centres of mass within 1e-6 m); the
                result goes to standard error

Exit status: 0 success; 1 the model has errors, has closed loops, or MuJoCo
disagrees (--check); 2 usage error, unreadable model, or --check in a padrob
built without MuJoCo. On failure nothing is written.
</translation>
    </message>
    <message>
        <location line="+48" />
        <source>--scene needs a file name</source>
        <translation>--scene needs a file name</translation>
    </message>
    <message>
        <location line="+3" />
        <source>--out needs a file name</source>
        <translation>--out needs a file name</translation>
    </message>
    <message>
        <location line="+4" />
        <location filename="../ide/cli/simulate.cpp" line="-42" />
        <source>--dt must be a positive number of seconds, not '%1'</source>
        <translation>--dt must be a positive number of seconds, not '%1'</translation>
    </message>
    <message>
        <location line="+9" />
        <source>give the format: --mjcf (the only one)</source>
        <translation>give the format: --mjcf (the only one)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>--check needs MuJoCo, and this padrob was built without it</source>
        <translation>--check needs MuJoCo, and this padrob was built without it</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+25" />
        <location line="+13" />
        <source>note: %1</source>
        <translation>note: %1</translation>
    </message>
    <message>
        <location line="-38" />
        <source>the model has no CONTACT: no geoms, and the scene is not exported</source>
        <translation>the model has no CONTACT: no geoms, and the scene is not exported</translation>
    </message>
    <message>
        <location line="+26" />
        <source>set in MuJoCo after loading: %1</source>
        <translation>set in MuJoCo after loading: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MuJoCo agrees with Padrob over %1 s (RK4, dt %2 s): the centres of mass are at most %3 m apart</source>
        <translation>MuJoCo agrees with Padrob over %1 s (RK4, dt %2 s): the centres of mass are at most %3 m apart</translation>
    </message>
    <message>
        <location line="+5" />
        <source>MuJoCo loads the export with its %1 geoms and contacts on</source>
        <translation>MuJoCo loads the export with its %1 geoms and contacts on</translation>
    </message>
    <message>
        <location line="+2" />
        <source>with contacts over %1 s (every joint passive, no limits): the centres of mass are at most %2 m apart; at the end:</source>
        <translation>with contacts over %1 s (every joint passive, no limits): the centres of mass are at most %2 m apart; at the end:</translation>
    </message>
    <message>
        <location line="+7" />
        <source>  body %1: Padrob %2, MuJoCo %3</source>
        <translation>  body %1: Padrob %2, MuJoCo %3</translation>
    </message>
    <message>
        <location line="+8" />
        <source>cannot write to standard output</source>
        <translation>cannot write to standard output</translation>
    </message>
    <message>
        <location filename="../ide/cli/inertia.cpp" line="-160" />
        <source>n/a (file: 0)</source>
        <translation>n/a (file: 0)</translation>
    </message>
    <message>
        <location line="+117" />
        <source>Usage: padrob inertia MODEL [--body I] [--write]

Computes each body's mass, centre of mass and inertia tensor (about the centre of
mass, in body axes) from its solids: the graphics (G) with MASS or RHO, combined
with the parallel-axis theorem. For each such body it prints the computed B line
beside the one in the file, the relative difference of the mass and of each
moment, and the principal moments.

  --body I   only body I
  --write    replace each computed body's B line in the file (its NAME and any
             comment are kept, every other line byte for byte), after copying
             the file to MODEL.bak

A model with errors (or a mesh that cannot be used) is not computed and not
written: its problems are printed as by 'padrob check' and the exit status is 1.
Exit status 2 on a usage error or a file that cannot be read or written.
</source>
        <translation>Usage: padrob inertia MODEL [--body I] [--write]

Computes each body's mass, centre of mass and inertia tensor (about the centre of
mass, in body axes) from its solids: the graphics (G) with MASS or RHO, combined
with the parallel-axis theorem. For each such body it prints the computed B line
beside the one in the file, the relative difference of the mass and of each
moment, and the principal moments.

  --body I   only body I
  --write    replace each computed body's B line in the file (its NAME and any
             comment are kept, every other line byte for byte), after copying
             the file to MODEL.bak

A model with errors (or a mesh that cannot be used) is not computed and not
written: its problems are printed as by 'padrob check' and the exit status is 1.
Exit status 2 on a usage error or a file that cannot be read or written.
</translation>
    </message>
    <message>
        <location line="+31" />
        <source>--body needs a body id</source>
        <translation>--body needs a body id</translation>
    </message>
    <message>
        <location line="+5" />
        <source>--body takes a body id (a positive integer), not '%1'</source>
        <translation>--body takes a body id (a positive integer), not '%1'</translation>
    </message>
    <message>
        <location line="+21" />
        <source>--body: the model has no body %1</source>
        <translation>--body: the model has no body %1</translation>
    </message>
    <message>
        <location line="+19" />
        <source>body %1 has no solids (graphics with MASS or RHO)</source>
        <translation>body %1 has no solids (graphics with MASS or RHO)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No body has solids (graphics with MASS or RHO): nothing to compute.</source>
        <translation>No body has solids (graphics with MASS or RHO): nothing to compute.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>cannot read '%1'</source>
        <translation>cannot read '%1'</translation>
    </message>
    <message>
        <location line="+13" />
        <source>file:</source>
        <translation>file:</translation>
    </message>
    <message>
        <location line="+0" />
        <source>computed:</source>
        <translation>computed:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>difference:</source>
        <translation>difference:</translation>
    </message>
    <message>
        <location line="+0" />
        <source>principal:</source>
        <translation>principal:</translation>
    </message>
    <message>
        <location line="+17" />
        <source>body %1</source>
        <translation>body %1</translation>
    </message>
    <message>
        <location line="+20" />
        <source>cannot find body %1's B statement in the file; nothing written</source>
        <translation>cannot find body %1's B statement in the file; nothing written</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the updated model would not load as computed; nothing written</source>
        <translation>the updated model would not load as computed; nothing written</translation>
    </message>
    <message>
        <location line="+8" />
        <source>cannot write the backup '%1'; nothing written</source>
        <translation>cannot write the backup '%1'; nothing written</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot write '%1'</source>
        <translation>cannot write '%1'</translation>
    </message>
    <message numerus="yes">
        <location line="+4" />
        <source>Wrote %n B line(s) to %1 (the old file is %2)</source>
        <translation>
            <numerusform>Wrote %n B line to %1 (the old file is %2)</numerusform>
            <numerusform>Wrote %n B lines to %1 (the old file is %2)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ide/cli/info_report.cpp" line="+55" />
        <source>dependent</source>
        <comment>role of a joint's coordinate</comment>
        <translation>dependent</translation>
    </message>
    <message>
        <location line="+1" />
        <source>loop-closure</source>
        <comment>role of a joint</comment>
        <translation>loop-closure</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent</source>
        <comment>role of a joint's coordinate</comment>
        <translation>independent</translation>
    </message>
    <message>
        <location line="+7" />
        <source>revolute</source>
        <comment>joint type (T 0)</comment>
        <translation>revolute</translation>
    </message>
    <message>
        <location line="+1" />
        <source>actuator</source>
        <comment>joint type (T 1)</comment>
        <translation>actuator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>prismatic</source>
        <comment>joint type (T 2)</comment>
        <translation>prismatic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>free</source>
        <comment>joint type (T 3)</comment>
        <translation>free</translation>
    </message>
    <message>
        <location line="+21" />
        <location line="+53" />
        <location line="+40" />
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location line="-68" />
        <source>Model: %1</source>
        <translation>Model: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gravity: %1 m/s²</source>
        <translation>Gravity: %1 m/s²</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bodies (%1 + ground), total mass %2 kg</source>
        <translation>Bodies (%1 + ground), total mass %2 kg</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+11" />
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <location line="-10" />
        <source>mass [kg]</source>
        <translation>mass [kg]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ixx Iyy Izz [kg m²]</source>
        <translation>Ixx Iyy Izz [kg m²]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>centre of mass</source>
        <translation>centre of mass</translation>
    </message>
    <message>
        <location line="+3" />
        <source>massless</source>
        <translation>massless</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Joints (%1)</source>
        <translation>Joints (%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>type</source>
        <translation>type</translation>
    </message>
    <message>
        <location line="+2" />
        <source>limits</source>
        <translation>limits</translation>
    </message>
    <message>
        <location line="+1" />
        <source>initial</source>
        <translation>initial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>role</source>
        <translation>role</translation>
    </message>
    <message>
        <location line="+1" />
        <source>drive</source>
        <translation>drive</translation>
    </message>
    <message>
        <location line="+10" />
        <source>passive</source>
        <translation>passive</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Spanning tree (parent body &lt;- joint &lt;- body):</source>
        <translation>Spanning tree (parent body &lt;- joint &lt;- body):</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 &lt;- joint %2 &lt;- %3</source>
        <translation>%1 &lt;- joint %2 &lt;- %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>written from B2 to B1</source>
        <translation>written from B2 to B1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Chains:</source>
        <translation>Chains:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: joints %2</source>
        <translation>%1: joints %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Loop-closure joints: %1</source>
        <translation>Loop-closure joints: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Degrees of freedom: %1</source>
        <translation>Degrees of freedom: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent coordinates (joints): %1</source>
        <translation>independent coordinates (joints): %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>dependent coordinates (joints): %1</source>
        <translation>dependent coordinates (joints): %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Fluid power: bulk modulus %1 Pa, laminar below %2 Pa</source>
        <translation>Fluid power: bulk modulus %1 Pa, laminar below %2 Pa</translation>
    </message>
    <message>
        <location line="+8" />
        <source>pump %1 %2: %3 L/min, %4 MPa, load-sensing (margin %5 MPa); drives %6</source>
        <translation>pump %1 %2: %3 L/min, %4 MPa, load-sensing (margin %5 MPa); drives %6</translation>
    </message>
    <message>
        <location line="+1" />
        <source>pump %1 %2: %3 L/min, %4 MPa, pressure-compensated%5; drives %6</source>
        <translation>pump %1 %2: %3 L/min, %4 MPa, pressure-compensated%5; drives %6</translation>
    </message>
    <message>
        <location filename="../ide/cli/main.cpp" line="-127" />
        <source>Usage: padrob COMMAND [OPTIONS] [ARGS]

Padrob builds real-time training simulators of machines from model files (.pad).

Commands:
  check MODEL...        check models and print their problems
  info MODEL [--json]   describe a model: bodies, joints, chains, degrees of freedom
  simulate MODEL --time T [OPTIONS]
                        simulate a model and write its trajectory as CSV
  inertia MODEL [--body I] [--write]
                        compute bodies' mass and inertia from their solids
  bench MODEL [OPTIONS]  time the solver on a model (and MuJoCo, when built in)
  export --mjcf MODEL [--out FILE]
                        write a tree model as MuJoCo's MJCF
  tutorial FILE [--input LOG | --demo] [--json]
                        check a tutorial, or run it against an input log and score it
  station TUTORIAL... --name NAME
                        a training station without a window on the centre's network
  instructor list|watch|send
                        the training centre's stations: list, watch and command them
  centre key|seal|bench the training centre's key, sealed secrets, scale benchmark

Options:
  -h, --help            show this help (or a command's: padrob COMMAND --help)
  --version             show the version
  --lang es|en          language of the messages, with any command (default: the
                        system's: LANGUAGE, LC_ALL, LC_MESSAGES or LANG)

Exit status: 0 success, 1 the model has errors, 2 usage error or unreadable file.
</source>
        <translation>Usage: padrob COMMAND [OPTIONS] [ARGS]

Padrob builds real-time training simulators of machines from model files (.pad).

Commands:
  check MODEL...        check models and print their problems
  info MODEL [--json]   describe a model: bodies, joints, chains, degrees of freedom
  simulate MODEL --time T [OPTIONS]
                        simulate a model and write its trajectory as CSV
  inertia MODEL [--body I] [--write]
                        compute bodies' mass and inertia from their solids
  bench MODEL [OPTIONS]  time the solver on a model (and MuJoCo, when built in)
  export --mjcf MODEL [--out FILE]
                        write a tree model as MuJoCo's MJCF
  tutorial FILE [--input LOG | --demo] [--json]
                        check a tutorial, or run it against an input log and score it
  station TUTORIAL... --name NAME
                        a training station without a window on the centre's network
  instructor list|watch|send
                        the training centre's stations: list, watch and command them
  centre key|seal|bench the training centre's key, sealed secrets, scale benchmark

Options:
  -h, --help            show this help (or a command's: padrob COMMAND --help)
  --version             show the version
  --lang es|en          language of the messages, with any command (default: the
                        system's: LANGUAGE, LC_ALL, LC_MESSAGES or LANG)

Exit status: 0 success, 1 the model has errors, 2 usage error or unreadable file.
</translation>
    </message>
    <message>
        <location line="+34" />
        <source>Usage: padrob check MODEL...

Reads each model file and prints every problem found, one per line, as
  file:line:column: error|warning: message [hint]
(the format compilers use, so editors can jump to each problem), then a summary.

Exit status: 0 when no model has errors (warnings are allowed), 1 when some model
has errors, 2 on a usage error or when a file cannot be read.
</source>
        <translation>Usage: padrob check MODEL...

Reads each model file and prints every problem found, one per line, as
  file:line:column: error|warning: message [hint]
(the format compilers use, so editors can jump to each problem), then a summary.

Exit status: 0 when no model has errors (warnings are allowed), 1 when some model
has errors, 2 on a usage error or when a file cannot be read.
</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Usage: padrob info MODEL [--json]

Describes a model: its bodies (mass, inertia), joints (type, bodies, limits,
initial value, drive), the spanning tree from ground, the loop-closure joints,
the kinematic chains, the degrees of freedom and which coordinates are
independent or dependent, and the total mass.

  --json   print one JSON object instead (format "padrob-info", version 1;
           documented in docs/cli.md)

A model with errors is not described: its problems are printed as by
'padrob check' and the exit status is 1 (2 if the file cannot be read).
</source>
        <translation>Usage: padrob info MODEL [--json]

Describes a model: its bodies (mass, inertia), joints (type, bodies, limits,
initial value, drive), the spanning tree from ground, the loop-closure joints,
the kinematic chains, the degrees of freedom and which coordinates are
independent or dependent, and the total mass.

  --json   print one JSON object instead (format "padrob-info", version 1;
           documented in docs/cli.md)

A model with errors is not described: its problems are printed as by
'padrob check' and the exit status is 1 (2 if the file cannot be read).
</translation>
    </message>
    <message numerus="yes">
        <location line="+35" />
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: ok (%2)</source>
        <translation>%1: ok (%2)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1: ok</source>
        <translation>%1: ok</translation>
    </message>
    <message numerus="yes">
        <location line="+2" />
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64" />
        <source>--lang needs a value: es or en</source>
        <translation>--lang needs a value: es or en</translation>
    </message>
    <message>
        <location line="+13" />
        <source>--lang must be es or en, not '%1'</source>
        <translation>--lang must be es or en, not '%1'</translation>
    </message>
    <message>
        <location line="+26" />
        <location line="+30" />
        <source>Try 'padrob --help'.</source>
        <translation>Try 'padrob --help'.</translation>
    </message>
    <message>
        <location line="-1" />
        <source>unknown command '%1'</source>
        <translation>unknown command '%1'</translation>
    </message>
    <message>
        <location filename="../ide/cli/mujoco_bench.cpp" line="+89" />
        <source>MuJoCo's virtual file system refused the MJCF</source>
        <translation>MuJoCo's virtual file system refused the MJCF</translation>
    </message>
    <message>
        <location line="+7" />
        <source>MuJoCo refused the exported MJCF: %1</source>
        <translation>MuJoCo refused the exported MJCF: %1</translation>
    </message>
    <message>
        <location line="+77" />
        <source>MuJoCo could not allocate its data</source>
        <translation>MuJoCo could not allocate its data</translation>
    </message>
    <message>
        <location line="-58" />
        <source>MuJoCo's model has no body '%1' or joint '%2'</source>
        <translation>MuJoCo's model has no body '%1' or joint '%2'</translation>
    </message>
    <message numerus="yes">
        <location line="+164" />
        <source>every joint passive in both: the model's %n drive(s) are not exported</source>
        <translation>
            <numerusform>every joint passive in both: the model's %n drive is not exported</numerusform>
            <numerusform>every joint passive in both: the model's %n drives are not exported</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3" />
        <source>joint limits off in both (%n joint(s) have them)</source>
        <translation>
            <numerusform>joint limits off in both (%n joint has them)</numerusform>
            <numerusform>joint limits off in both (%n joints have them)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4" />
        <source>Padrob runs without the model's %n applied force(s) (F): they are not exported</source>
        <translation>
            <numerusform>Padrob runs without the model's %n applied force (F): it is not exported</numerusform>
            <numerusform>Padrob runs without the model's %n applied forces (F): they are not exported</numerusform>
        </translation>
    </message>
    <message>
        <location line="-79" />
        <location line="+104" />
        <source>Padrob failed: %1</source>
        <translation>Padrob failed: %1</translation>
    </message>
    <message>
        <location line="-20" />
        <source>the agreement is checked without contacts (MuJoCo's export there has no geoms)</source>
        <translation>the agreement is checked without contacts (MuJoCo's export there has no geoms)</translation>
    </message>
    <message>
        <location line="+34" />
        <source>MuJoCo and Padrob disagree: the centre of mass of body %1 is %2 m apart at t = %3 s (tolerance %4 m; Padrob %5, MuJoCo %6)</source>
        <translation>MuJoCo and Padrob disagree: the centre of mass of body %1 is %2 m apart at t = %3 s (tolerance %4 m; Padrob %5, MuJoCo %6)</translation>
    </message>
    <message numerus="yes">
        <location line="+34" />
        <source>MuJoCo warned %n time(s): %1</source>
        <translation>
            <numerusform>MuJoCo warned %n time: %1</numerusform>
            <numerusform>MuJoCo warned %n times: %1</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ide/cli/simulate.cpp" line="-177" />
        <source>warning: %1</source>
        <translation>warning: %1</translation>
    </message>
    <message>
        <location line="+54" />
        <source>--weld takes T:A:B: a time [s] and two body ids, to weld body B to body A (0 = the ground), e.g. 0.5:0:2; not '%1'</source>
        <translation>--weld takes T:A:B: a time [s] and two body ids, to weld body B to body A (0 = the ground), e.g. 0.5:0:2; not '%1'</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--release takes T:A:B: a time [s] and two body ids, to release the weld of body B to body A (0 = the ground), e.g. 1.5:0:2; not '%1'</source>
        <translation>--release takes T:A:B: a time [s] and two body ids, to release the weld of body B to body A (0 = the ground), e.g. 1.5:0:2; not '%1'</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the time must be a finite number of seconds ≥ 0 (from the start), not '%1'</source>
        <translation>the time must be a finite number of seconds ≥ 0 (from the start), not '%1'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>cannot weld a body to itself: give two different bodies A and B</source>
        <translation>cannot weld a body to itself: give two different bodies A and B</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cannot release a body from itself: give the two bodies of a --weld</source>
        <translation>cannot release a body from itself: give the two bodies of a --weld</translation>
    </message>
    <message>
        <location line="+6" />
        <source>the ground cannot be welded to a body: put the ground as A, '%1'</source>
        <translation>the ground cannot be welded to a body: put the ground as A, '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the ground is never the welded body B: a weld to the ground is written with the ground as A, '%1'</source>
        <translation>the ground is never the welded body B: a weld to the ground is written with the ground as A, '%1'</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Usage: padrob simulate MODEL --time T [OPTIONS]

Simulates the model for T seconds and writes its trajectory as CSV.

  --time T              simulated time [s] (required, &gt; 0)
  --dt H                step [s] (default 0.001): the RK4 step, and how often the
                        inputs are read and output rows may be written
  --integrator M        rk4 (fixed step, the real-time integrator; default) or
                        adaptive (error-controlled, for accuracy)
  --rtol R              relative tolerance of the adaptive integrator (default 1e-8)
  --input FILE.csv      operator commands: a column t and one column u&lt;joint id&gt; per
                        drive, values in [-1, 1], held between rows
  --input-log LOG       replay a recorded input log (raw device readings, from
                        padrob-studio's Station workspace) through a station profile,
                        with its timing; instead of --input
  --profile P           the profile for --input-log: a .json file, or the name of one
                        of the model's profiles (default: the one made for the model:
                        keyboard pairs in order, gamepad in banks)
  --set J=VALUE         initial coordinate of joint J (overrides QI; T 1: length)
  --rate J=VALUE        initial rate of joint J (overrides VI)
  --passive             ignore every drive (all joints passive)
  --no-limits           ignore the joint limits LL/UL
  --every N             write one row every N steps (default 1)
  --out FILE.csv        write the CSV there (default: standard output)
  --weld T:A:B          at time T [s] weld body B to body A (0 = the ground) at
                        their relative pose then; repeatable
  --release T:A:B       at time T [s] release the weld of body B to body A;
                        repeatable
  --scene FILE.pad      a scene (ground graphics only, e.g. a mill): under CONTACT
                        the model's solids touch its solids too

Columns: t; q&lt;j&gt; for every joint j in id order (loop-closing joints too;
q&lt;j&gt;x q&lt;j&gt;y q&lt;j&gt;z for a free joint, T 3: its body's translation along B1's
joint axes); qd&lt;j&gt; likewise; ang&lt;j&gt; (the angle, rad) for every
pivoted-actuator (T 1) joint, whose q&lt;j&gt; is the length;
x&lt;i&gt; y&lt;i&gt; z&lt;i&gt;, the world position of the centre of mass of every body i;
F&lt;j&gt;, the force or torque of every drive; pA&lt;j&gt; pB&lt;j&gt;, the chamber pressures
[Pa] of every fluid-power drive (CYL, HMOTOR) in joint id order, then pP&lt;id&gt;,
the supply pressure of every pump; E, the mechanical energy (kinetic +
gravitational) [J]. Events (limits hit and left, relief valves opening and
closing, pumps saturating, cavitation, welds made and released, a closed loop
locking up) are printed on standard error, one per line.

Welds: the simulation stops exactly at each T (between output rows if T is not
a multiple of --dt; the rows stay every --dt), makes or releases the weld and
goes on; a row at T shows the state after it. Several at one T apply in the
order given. B is never the ground (put the ground as A); a body other than
the ground is in one weld at a time, and --release needs that weld in force
at T (else the run fails, exit status 1).

Exit status: 0 success; 1 the model has errors or the simulation failed;
2 usage error or unreadable input. On failure no output file is left behind.
</source>
        <translation>Usage: padrob simulate MODEL --time T [OPTIONS]

Simulates the model for T seconds and writes its trajectory as CSV.

  --time T              simulated time [s] (required, &gt; 0)
  --dt H                step [s] (default 0.001): the RK4 step, and how often the
                        inputs are read and output rows may be written
  --integrator M        rk4 (fixed step, the real-time integrator; default) or
                        adaptive (error-controlled, for accuracy)
  --rtol R              relative tolerance of the adaptive integrator (default 1e-8)
  --input FILE.csv      operator commands: a column t and one column u&lt;joint id&gt; per
                        drive, values in [-1, 1], held between rows
  --input-log LOG       replay a recorded input log (raw device readings, from
                        padrob-studio's Station workspace) through a station profile,
                        with its timing; instead of --input
  --profile P           the profile for --input-log: a .json file, or the name of one
                        of the model's profiles (default: the one made for the model:
                        keyboard pairs in order, gamepad in banks)
  --set J=VALUE         initial coordinate of joint J (overrides QI; T 1: length)
  --rate J=VALUE        initial rate of joint J (overrides VI)
  --passive             ignore every drive (all joints passive)
  --no-limits           ignore the joint limits LL/UL
  --every N             write one row every N steps (default 1)
  --out FILE.csv        write the CSV there (default: standard output)
  --weld T:A:B          at time T [s] weld body B to body A (0 = the ground) at
                        their relative pose then; repeatable
  --release T:A:B       at time T [s] release the weld of body B to body A;
                        repeatable
  --scene FILE.pad      a scene (ground graphics only, e.g. a mill): under CONTACT
                        the model's solids touch its solids too

Columns: t; q&lt;j&gt; for every joint j in id order (loop-closing joints too;
q&lt;j&gt;x q&lt;j&gt;y q&lt;j&gt;z for a free joint, T 3: its body's translation along B1's
joint axes); qd&lt;j&gt; likewise; ang&lt;j&gt; (the angle, rad) for every
pivoted-actuator (T 1) joint, whose q&lt;j&gt; is the length;
x&lt;i&gt; y&lt;i&gt; z&lt;i&gt;, the world position of the centre of mass of every body i;
F&lt;j&gt;, the force or torque of every drive; pA&lt;j&gt; pB&lt;j&gt;, the chamber pressures
[Pa] of every fluid-power drive (CYL, HMOTOR) in joint id order, then pP&lt;id&gt;,
the supply pressure of every pump; E, the mechanical energy (kinetic +
gravitational) [J]. Events (limits hit and left, relief valves opening and
closing, pumps saturating, cavitation, welds made and released, a closed loop
locking up) are printed on standard error, one per line.

Welds: the simulation stops exactly at each T (between output rows if T is not
a multiple of --dt; the rows stay every --dt), makes or releases the weld and
goes on; a row at T shows the state after it. Several at one T apply in the
order given. B is never the ground (put the ground as A); a body other than
the ground is in one weld at a time, and --release needs that weld in force
at T (else the run fails, exit status 1).

Exit status: 0 success; 1 the model has errors or the simulation failed;
2 usage error or unreadable input. On failure no output file is left behind.
</translation>
    </message>
    <message>
        <location line="+85" />
        <source>--time must be a positive number of seconds, not '%1'</source>
        <translation>--time must be a positive number of seconds, not '%1'</translation>
    </message>
    <message>
        <location line="+7" />
        <source>--rtol must be a number between 0 and 1, not '%1'</source>
        <translation>--rtol must be a number between 0 and 1, not '%1'</translation>
    </message>
    <message>
        <location line="+4" />
        <source>--every must be a whole number ≥ 1, not '%1'</source>
        <translation>--every must be a whole number ≥ 1, not '%1'</translation>
    </message>
    <message>
        <location line="+24" />
        <location line="+35" />
        <source>%1 takes J=VALUE (a joint id and a number), not '%2'</source>
        <translation>%1 takes J=VALUE (a joint id and a number), not '%2'</translation>
    </message>
    <message>
        <location line="-24" />
        <source>--time is required</source>
        <translation>--time is required</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--input and --input-log cannot be combined</source>
        <translation>--input and --input-log cannot be combined</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--profile goes with --input-log</source>
        <translation>--profile goes with --input-log</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--dt is longer than --time</source>
        <translation>--dt is longer than --time</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--time / --dt is more than 1e9 steps</source>
        <translation>--time / --dt is more than 1e9 steps</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the time is after the end of the simulation (--time %1 s): give a T between 0 and --time</source>
        <translation>the time is after the end of the simulation (--time %1 s): give a T between 0 and --time</translation>
    </message>
    <message>
        <location line="+22" />
        <source>%1: the model has no joint %2</source>
        <translation>%1: the model has no joint %2</translation>
    </message>
    <message>
        <location line="+25" />
        <source>0 (the ground)</source>
        <translation>0 (the ground)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the model has no body %1; its bodies are %2</source>
        <translation>the model has no body %1; its bodies are %2</translation>
    </message>
    <message>
        <location line="+187" />
        <source>the adaptive integrator failed too: check the model's masses, springs and forces</source>
        <translation>the adaptive integrator failed too: check the model's masses, springs and forces</translation>
    </message>
    <message>
        <location line="+1" />
        <source>run it again with a smaller --dt (now %1 s; e.g. --dt %2) or with --integrator adaptive</source>
        <translation>run it again with a smaller --dt (now %1 s; e.g. --dt %2) or with --integrator adaptive</translation>
    </message>
    <message>
        <location filename="../ide/cli/tutorial.cpp" line="-170" />
        <source>Usage: padrob tutorial FILE [--input LOG | --demo] [OPTIONS]

Checks a tutorial file (.tut) and, with --input or --demo, runs it without a window:
the input log is replayed through the station profile into the simulation while the
tutorial's checker watches the goals, the grasp, collisions, overloads and time, and
scores the run. Prints whether it passed, the score breakdown and the events with
their times.

  --input LOG           replay this input log (raw device readings, as padrob-studio's
                        Station and Train workspaces record them)
  --demo                replay the tutorial's own demonstration (its DEMO statement)
  --profile P           the station profile for the log: a .json file or the name of
                        one of the model's profiles (default: the tutorial's PROFILE)
  --autopilot PATH --record OUT [--camera CAM]
                        fly the joint targets of PATH with the levers of a virtual
                        console and record them to OUT (a demonstration; see
                        docs/training.md), and a chase camera to CAM, then print
                        the result of that run
  --lang es|en          language of the tutorial's texts and of the messages
                        (default: the system's; an option of every command)
  --json                print the result as one JSON object

Without --input, --demo or --autopilot it only checks the tutorial and its model.

Exit status: 0 the tutorial is fine (checked) or the run passed; 1 the run failed;
2 bad input: a usage error, a tutorial with errors, an unreadable log.
</source>
        <translation>Usage: padrob tutorial FILE [--input LOG | --demo] [OPTIONS]

Checks a tutorial file (.tut) and, with --input or --demo, runs it without a window:
the input log is replayed through the station profile into the simulation while the
tutorial's checker watches the goals, the grasp, collisions, overloads and time, and
scores the run. Prints whether it passed, the score breakdown and the events with
their times.

  --input LOG           replay this input log (raw device readings, as padrob-studio's
                        Station and Train workspaces record them)
  --demo                replay the tutorial's own demonstration (its DEMO statement)
  --profile P           the station profile for the log: a .json file or the name of
                        one of the model's profiles (default: the tutorial's PROFILE)
  --autopilot PATH --record OUT [--camera CAM]
                        fly the joint targets of PATH with the levers of a virtual
                        console and record them to OUT (a demonstration; see
                        docs/training.md), and a chase camera to CAM, then print
                        the result of that run
  --lang es|en          language of the tutorial's texts and of the messages
                        (default: the system's; an option of every command)
  --json                print the result as one JSON object

Without --input, --demo or --autopilot it only checks the tutorial and its model.

Exit status: 0 the tutorial is fine (checked) or the run passed; 1 the run failed;
2 bad input: a usage error, a tutorial with errors, an unreadable log.
</translation>
    </message>
    <message>
        <location line="+36" />
        <source>every goal done</source>
        <translation>every goal done</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the time ran out</source>
        <translation>the time ran out</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a hard hit</source>
        <translation>a hard hit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a worker was touched</source>
        <translation>a worker was touched</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the input ended</source>
        <translation>the input ended</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the simulation failed</source>
        <translation>the simulation failed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <location line="+9" />
        <source>PASSED</source>
        <translation>PASSED</translation>
    </message>
    <message>
        <location line="+0" />
        <source>FAILED</source>
        <translation>FAILED</translation>
    </message>
    <message>
        <location line="+2" />
        <source>score %1/100 (pass mark %2), %3 s, %4/%5 goals, end: %6</source>
        <translation>score %1/100 (pass mark %2), %3 s, %4/%5 goals, end: %6</translation>
    </message>
    <message>
        <location line="+7" />
        <source>%1 s (par %2 s, limit %3 s)</source>
        <translation>%1 s (par %2 s, limit %3 s)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 % efficient (%2 m, ideal %3 m)</source>
        <translation>%1 % efficient (%2 m, ideal %3 m)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>RMS jerk %1 m/s3 (zero points at %2)</source>
        <translation>RMS jerk %1 m/s3 (zero points at %2)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 penalty points</source>
        <translation>%1 penalty points</translation>
    </message>
    <message>
        <location line="+4" />
        <source>events:</source>
        <translation>events:</translation>
    </message>
    <message>
        <location line="+7" />
        <source>to improve:</source>
        <translation>to improve:</translation>
    </message>
    <message>
        <location line="+95" />
        <source>one tutorial file at a time</source>
        <translation>one tutorial file at a time</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no tutorial file given</source>
        <translation>no tutorial file given</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--input, --demo and --autopilot exclude each other</source>
        <translation>--input, --demo and --autopilot exclude each other</translation>
    </message>
    <message>
        <location line="+2" />
        <source>--autopilot and --record go together</source>
        <translation>--autopilot and --record go together</translation>
    </message>
    <message>
        <location line="+1" />
        <source>--camera goes with --autopilot</source>
        <translation>--camera goes with --autopilot</translation>
    </message>
    <message numerus="yes">
        <location line="+10" />
        <source>OK (%n goal(s), no demonstration)</source>
        <translation>
            <numerusform>OK (%n goal, no demonstration)</numerusform>
            <numerusform>OK (%n goals, no demonstration)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>OK (%n goal(s))</source>
        <translation>
            <numerusform>OK (%n goal)</numerusform>
            <numerusform>OK (%n goals)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+47" />
        <source>the tutorial has no usable demonstration (DEMO)</source>
        <translation>the tutorial has no usable demonstration (DEMO)</translation>
    </message>
    <message>
        <location filename="../ide/cli/centre.cpp" line="-681" />
        <source>--domain must be a whole number from 0 to 232, not '%1'</source>
        <translation>--domain must be a whole number from 0 to 232, not '%1'</translation>
    </message>
    <message>
        <location line="+52" />
        <location line="+10" />
        <source>--records-server must be USER@HOST:PORT/DATABASE, not '%1'</source>
        <translation>--records-server must be USER@HOST:PORT/DATABASE, not '%1'</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Usage: padrob station TUTORIAL... --name NAME [OPTIONS]

Runs a training station without a window on the centre's network: the tutorials'
machine is simulated in real time, its state is streamed for display nodes
(padrob-studio --display-of NAME) and the instructor, its events are sent as they
happen, and the instructor's signed commands are obeyed: start, pause, resume,
reset and stop a tutorial, inject and clear faults. Every attempt is recorded.
Runs until interrupted (Ctrl+C or SIGTERM), then says it is leaving.

  --name NAME           the station's name, unique in the centre
  --profile P           the operator's devices: a station profile of the model (its
                        name, or a .json file; docs/station.md): gamepads, joysticks,
                        the serial valve console
  --demo                the operator's input is each tutorial's demonstration
                        (a showcase, or a test)
                        Without either, the levers rest.
  --records FILE        record the attempts in this SQLite file (the station's journal)
  --records-server USER@HOST:PORT/DATABASE
                        and sync them to the centre's PostgreSQL server; while it is
                        out of reach the journal keeps them (docs/records.md)
  --records-password FILE
                        the server's password, sealed with the centre's key by
                        'padrob centre seal' (never stored in plain text)
  --for SECONDS         stop after this long
</source>
        <translation>Usage: padrob station TUTORIAL... --name NAME [OPTIONS]

Runs a training station without a window on the centre's network: the tutorials'
machine is simulated in real time, its state is streamed for display nodes
(padrob-studio --display-of NAME) and the instructor, its events are sent as they
happen, and the instructor's signed commands are obeyed: start, pause, resume,
reset and stop a tutorial, inject and clear faults. Every attempt is recorded.
Runs until interrupted (Ctrl+C or SIGTERM), then says it is leaving.

  --name NAME           the station's name, unique in the centre
  --profile P           the operator's devices: a station profile of the model (its
                        name, or a .json file; docs/station.md): gamepads, joysticks,
                        the serial valve console
  --demo                the operator's input is each tutorial's demonstration
                        (a showcase, or a test)
                        Without either, the levers rest.
  --records FILE        record the attempts in this SQLite file (the station's journal)
  --records-server USER@HOST:PORT/DATABASE
                        and sync them to the centre's PostgreSQL server; while it is
                        out of reach the journal keeps them (docs/records.md)
  --records-password FILE
                        the server's password, sealed with the centre's key by
                        'padrob centre seal' (never stored in plain text)
  --for SECONDS         stop after this long
</translation>
    </message>
    <message>
        <location line="+61" />
        <source>--for must be a positive number of seconds, not '%1'</source>
        <translation>--for must be a positive number of seconds, not '%1'</translation>
    </message>
    <message>
        <location line="+8" />
        <source>--name is required: the station's name in the centre</source>
        <translation>--name is required: the station's name in the centre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>give at least one tutorial file (.tut)</source>
        <translation>give at least one tutorial file (.tut)</translation>
    </message>
    <message>
        <location line="-175" />
        <source>Network options (every node of a centre uses the same):
  --domain N            the centre's DDS domain, 0-232 (default 0)
  --key FILE            the centre's key (make one with 'padrob centre key FILE'):
                        every node signs what it says with it and ignores what is
                        not signed with it; stations refuse commands without it
  --interface NAME      the network interface to use (name or address; repeatable)
  --peer ADDRESS        discover the other computers by unicast at ADDRESS
                        (repeatable; without it, multicast)
  --loopback            this computer only (--interface 127.0.0.1 --peer 127.0.0.1)
  --security DIR        DDS Security: authenticated, access-controlled, encrypted
                        traffic, with the centre's PKI in DIR and this node's
                        identity in DIR/nodes/NAME (see 'padrob centre pki')
</source>
        <translation>Network options (every node of a centre uses the same):
  --domain N            the centre's DDS domain, 0-232 (default 0)
  --key FILE            the centre's key (make one with 'padrob centre key FILE'):
                        every node signs what it says with it and ignores what is
                        not signed with it; stations refuse commands without it
  --interface NAME      the network interface to use (name or address; repeatable)
  --peer ADDRESS        discover the other computers by unicast at ADDRESS
                        (repeatable; without it, multicast)
  --loopback            this computer only (--interface 127.0.0.1 --peer 127.0.0.1)
  --security DIR        DDS Security: authenticated, access-controlled, encrypted
                        traffic, with the centre's PKI in DIR and this node's
                        identity in DIR/nodes/NAME (see 'padrob centre pki')
</translation>
    </message>
    <message>
        <location line="+177" />
        <source>--key FILE is required: the centre's key signs what the station says (no instructor or display believes it otherwise) and checks the instructor's commands</source>
        <translation>--key FILE is required: the centre's key signs what the station says (no instructor or display believes it otherwise) and checks the instructor's commands</translation>
    </message>
    <message>
        <location line="+35" />
        <source>cannot open the sealed password in %1: it must be made by 'padrob centre seal' with this centre's key</source>
        <translation>cannot open the sealed password in %1: it must be made by 'padrob centre seal' with this centre's key</translation>
    </message>
    <message>
        <location line="+10" />
        <source>--records-server needs --records FILE, the station's local journal</source>
        <translation>--records-server needs --records FILE, the station's local journal</translation>
    </message>
    <message>
        <location line="+35" />
        <source>station %1: %2
</source>
        <translation>station %1: %2
</translation>
    </message>
    <message>
        <location line="+18" />
        <source>station %1: on the centre's network (domain %2), ready
</source>
        <translation>station %1: on the centre's network (domain %2), ready
</translation>
    </message>
    <message>
        <location line="+4" />
        <source>station %1: left the centre's network
</source>
        <translation>station %1: left the centre's network
</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Usage: padrob instructor list|watch|send ... [OPTIONS]

The instructor's station without a window:
  list [--wait S]       the stations on the network after listening S seconds
                        (default 2): name, status, tutorial, time, score, warnings
  watch [--for S]       print the stations' events and comings and goings as they
                        happen (for S seconds; default until interrupted)
  send STATION COMMAND [ARG [ARG2]] [--value V] [--timeout S]
                        send a signed command and wait for the station's answer:
                          start [TUTORIAL [OPERATOR]], pause, resume, reset, stop,
                          inject FAULT [DRIVE|X,Y,Z], clear FAULT [DRIVE]
                        faults: hose-burst DRIVE, stuck-valve DRIVE [--value U],
                          worker-in X,Y,Z [--value WORKER], power-cut
  --name NAME           the instructor's name (default: instructor@HOST)
  --json                JSON output (one object; watch: one per line)

Exit status: 0 done or accepted, 1 the station refused or did not answer,
2 usage error.
</source>
        <translation>Usage: padrob instructor list|watch|send ... [OPTIONS]

The instructor's station without a window:
  list [--wait S]       the stations on the network after listening S seconds
                        (default 2): name, status, tutorial, time, score, warnings
  watch [--for S]       print the stations' events and comings and goings as they
                        happen (for S seconds; default until interrupted)
  send STATION COMMAND [ARG [ARG2]] [--value V] [--timeout S]
                        send a signed command and wait for the station's answer:
                          start [TUTORIAL [OPERATOR]], pause, resume, reset, stop,
                          inject FAULT [DRIVE|X,Y,Z], clear FAULT [DRIVE]
                        faults: hose-burst DRIVE, stuck-valve DRIVE [--value U],
                          worker-in X,Y,Z [--value WORKER], power-cut
  --name NAME           the instructor's name (default: instructor@HOST)
  --json                JSON output (one object; watch: one per line)

Exit status: 0 done or accepted, 1 the station refused or did not answer,
2 usage error.
</translation>
    </message>
    <message>
        <location line="+24" />
        <source>on the network</source>
        <translation>on the network</translation>
    </message>
    <message>
        <location line="+1" />
        <source>silent</source>
        <translation>silent</translation>
    </message>
    <message>
        <location line="+1" />
        <source>gone (it left)</source>
        <translation>gone (it left)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>paused</source>
        <translation>paused</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ended</source>
        <translation>ended</translation>
    </message>
    <message>
        <location line="+70" />
        <source>the station has no centre key and takes no commands</source>
        <translation>the station has no centre key and takes no commands</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the signature does not match the station's centre key</source>
        <translation>the signature does not match the station's centre key</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the command is too old or from the future (check the computers' clocks)</source>
        <translation>the command is too old or from the future (check the computers' clocks)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a replayed command (its nonce was already used)</source>
        <translation>a replayed command (its nonce was already used)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a field of the command is longer than the centre allows</source>
        <translation>a field of the command is longer than the centre allows</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station took too many commands in the last 30 s; try again shortly</source>
        <translation>the station took too many commands in the last 30 s; try again shortly</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station has no such tutorial</source>
        <translation>the station has no such tutorial</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no attempt is running</source>
        <translation>no attempt is running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the attempt is not paused</source>
        <translation>the attempt is not paused</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no such fault (hose-burst, stuck-valve, worker-in, power-cut)</source>
        <translation>no such fault (hose-burst, stuck-valve, worker-in, power-cut)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no such command</source>
        <translation>no such command</translation>
    </message>
    <message>
        <location line="+36" />
        <location line="+264" />
        <source>%1 needs a number</source>
        <translation>%1 needs a number</translation>
    </message>
    <message>
        <location line="-256" />
        <source>say what to do: list, watch or send</source>
        <translation>say what to do: list, watch or send</translation>
    </message>
    <message>
        <location line="+3" />
        <source>unknown instructor command '%1'</source>
        <translation>unknown instructor command '%1'</translation>
    </message>
    <message>
        <location line="+1" />
        <source>send needs a station and a command</source>
        <translation>send needs a station and a command</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the centre's key is required (--key FILE): what the stations say is signed with it, and so are the commands</source>
        <translation>the centre's key is required (--key FILE): what the stations say is signed with it, and so are the commands</translation>
    </message>
    <message>
        <location line="+156" />
        <location line="+4" />
        <source>expected: padrob centre key --key CENTRE-KEY --node NAME FILE</source>
        <translation>expected: padrob centre key --key CENTRE-KEY --node NAME FILE</translation>
    </message>
    <message>
        <location line="+8" />
        <source>node %1's key in %2 (fingerprint %3), from the centre key %4
</source>
        <translation>node %1's key in %2 (fingerprint %3), from the centre key %4
</translation>
    </message>
    <message>
        <location line="+90" />
        <source>no tutorial file %1 (give --tutorial FILE)</source>
        <translation>no tutorial file %1 (give --tutorial FILE)</translation>
    </message>
    <message>
        <location line="-223" />
        <source>no station answered
</source>
        <translation>no station answered
</translation>
    </message>
    <message>
        <location line="+18" />
        <source>%1 is %2
</source>
        <translation>%1 is %2
</translation>
    </message>
    <message>
        <location line="+16" />
        <source>station %1 did not answer</source>
        <translation>station %1 did not answer</translation>
    </message>
    <message>
        <location line="+30" />
        <source>station %1 did not answer the command</source>
        <translation>station %1 did not answer the command</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 done
</source>
        <translation>%1: %2 done
</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 refused %2: %3
</source>
        <translation>%1 refused %2: %3
</translation>
    </message>
    <message>
        <location line="+65" />
        <source>expected: padrob centre seal --key FILE</source>
        <translation>expected: padrob centre seal --key FILE</translation>
    </message>
    <message>
        <location line="+10" />
        <source>give the secret on standard input (one line)</source>
        <translation>give the secret on standard input (one line)</translation>
    </message>
    <message>
        <location line="+20" />
        <source>expected: padrob centre pki DIR [--node NAME]...</source>
        <translation>expected: padrob centre pki DIR [--node NAME]...</translation>
    </message>
    <message>
        <location line="+8" />
        <source>new centre PKI in %1 (identity CA, permissions CA, signed governance)
</source>
        <translation>new centre PKI in %1 (identity CA, permissions CA, signed governance)
</translation>
    </message>
    <message>
        <location line="+7" />
        <source>identity and permissions of node %1 in %2
</source>
        <translation>identity and permissions of node %1 in %2
</translation>
    </message>
    <message>
        <location line="+21" />
        <source>--stations needs a whole number from 1 to 64</source>
        <translation>--stations needs a whole number from 1 to 64</translation>
    </message>
    <message>
        <location line="+96" />
        <source>only %1 of %2 stations were heard</source>
        <translation>only %1 of %2 stations were heard</translation>
    </message>
    <message>
        <location line="+61" />
        <source>%1 stations streaming to one instructor for %2 s (%3 states):
</source>
        <translation>%1 stations streaming to one instructor for %2 s (%3 states):
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  state rate per station: median %1 Hz, lowest %2 Hz; most lost: %3 %
</source>
        <translation>  state rate per station: median %1 Hz, lowest %2 Hz; most lost: %3 %
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  latency, station to instructor: median %1 ms, 99th percentile %2 ms, max %3 ms
</source>
        <translation>  latency, station to instructor: median %1 ms, 99th percentile %2 ms, max %3 ms
</translation>
    </message>
    <message>
        <location line="+2" />
        <source>  CPU: the instructor %1 % of a core; each station (median) %2 %
</source>
        <translation>  CPU: the instructor %1 % of a core; each station (median) %2 %
</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Usage: padrob centre key FILE
       padrob centre key --key CENTRE-KEY --node NAME FILE
       padrob centre seal --key FILE &lt; SECRET
       padrob centre bench [--stations N] [--seconds S] [--tutorial FILE] [--json]
       padrob centre pki DIR [--node NAME]...

key: makes a new centre key (32 random bytes) in FILE, readable by its owner only.
Copy it to every station, instructor and display of the centre (padrob station
--key, padrob instructor --key, padrob-studio --centre-key): every message is
signed with it, and what is not is ignored (commands: refused). An existing file
is never replaced. With --node NAME: node NAME's own key, derived from the
centre's key, for a station (padrob station --name NAME --key FILE): it signs
only that station's messages and checks only the commands for it, so the
station cannot pass for another. Instructors keep the centre's key.

seal: prints the line read from standard input (the records server's password)
sealed with the centre's key, for padrob station --records-password FILE.

bench: starts N headless stations (default 16) on this computer, each running the
tutorial's demonstration in real time and streaming its state at 60 Hz, and measures
at one instructor the state rate, the latency from station to instructor and the CPU
used (docs/performance.md).

pki: makes the centre's PKI for DDS Security in DIR (an identity CA, a permissions
CA and the signed governance document); with --node NAME, issues node NAME's
identity and permissions (valid 10 years) in DIR/nodes/NAME. Copy to each node
identity_ca.pem, permissions_ca.pem, governance.p7s and its nodes/NAME folder,
never the .key files of the CAs; then run it with --security DIR.
</source>
        <translation>Usage: padrob centre key FILE
       padrob centre key --key CENTRE-KEY --node NAME FILE
       padrob centre seal --key FILE &lt; SECRET
       padrob centre bench [--stations N] [--seconds S] [--tutorial FILE] [--json]
       padrob centre pki DIR [--node NAME]...

key: makes a new centre key (32 random bytes) in FILE, readable by its owner only.
Copy it to every station, instructor and display of the centre (padrob station
--key, padrob instructor --key, padrob-studio --centre-key): every message is
signed with it, and what is not is ignored (commands: refused). An existing file
is never replaced. With --node NAME: node NAME's own key, derived from the
centre's key, for a station (padrob station --name NAME --key FILE): it signs
only that station's messages and checks only the commands for it, so the
station cannot pass for another. Instructors keep the centre's key.

seal: prints the line read from standard input (the records server's password)
sealed with the centre's key, for padrob station --records-password FILE.

bench: starts N headless stations (default 16) on this computer, each running the
tutorial's demonstration in real time and streaming its state at 60 Hz, and measures
at one instructor the state rate, the latency from station to instructor and the CPU
used (docs/performance.md).

pki: makes the centre's PKI for DDS Security in DIR (an identity CA, a permissions
CA and the signed governance document); with --node NAME, issues node NAME's
identity and permissions (valid 10 years) in DIR/nodes/NAME. Copy to each node
identity_ca.pem, permissions_ca.pem, governance.p7s and its nodes/NAME folder,
never the .key files of the CAs; then run it with --security DIR.
</translation>
    </message>
    <message>
        <location line="+30" />
        <source>expected: padrob centre key FILE</source>
        <translation>expected: padrob centre key FILE</translation>
    </message>
    <message>
        <location line="+9" />
        <source>new centre key in %1 (fingerprint %2)
</source>
        <translation>new centre key in %1 (fingerprint %2)
</translation>
    </message>
</context>
<context>
    <name>studio::AttemptScreen</name>
    <message>
        <location filename="../ide/studio/train/attempt_screen.cpp" line="+168" />
        <source>Esc or Stop ends the attempt.</source>
        <translation>Esc or Stop ends the attempt.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Show the expert</source>
        <translation>Show the expert</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Your trainer chooses whether the expert is shown.</source>
        <translation>Your trainer chooses whether the expert is shown.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The demonstration runs beside the attempt, drawn translucent.</source>
        <translation>The demonstration runs beside the attempt, drawn translucent.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hydraulics</source>
        <translation>Hydraulics</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The pump, the spools and the chamber pressures beside the view.</source>
        <translation>The pump, the spools and the chamber pressures beside the view.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>View:</source>
        <translation>View:</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Three screens (−60°, 0°, +60°)</source>
        <translation>Three screens (−60°, 0°, +60°)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <location line="+69" />
        <source>Controls:</source>
        <translation>Controls:</translation>
    </message>
    <message>
        <location line="+101" />
        <source>Goal %1 of %2</source>
        <translation>Goal %1 of %2</translation>
    </message>
    <message>
        <location line="+57" />
        <source>Distance: %1 m</source>
        <translation>Distance: %1 m</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Angle: %1° off (within %2°)</source>
        <translation>Angle: %1° off (within %2°)</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Hold: %1 s more</source>
        <translation>Hold: %1 s more</translation>
    </message>
    <message>
        <location line="+4" />
        <source>come within %1 m</source>
        <translation>come within %1 m</translation>
    </message>
    <message>
        <location line="+2" />
        <source>align the load: %1° off</source>
        <translation>align the load: %1° off</translation>
    </message>
    <message>
        <location line="+0" />
        <source>align the head: %1° off</source>
        <translation>align the head: %1° off</translation>
    </message>
    <message>
        <location line="+2" />
        <source>hold the load in the claws</source>
        <translation>hold the load in the claws</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hold %1 s</source>
        <translation>Hold %1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hold %1 s once you %2</source>
        <translation>Hold %1 s once you %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source> and </source>
        <translation> and </translation>
    </message>
    <message>
        <location line="-71" />
        <source>All goals done</source>
        <translation>All goals done</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Time: %1 / %2 s</source>
        <translation>Time: %1 / %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Penalties: %1</source>
        <translation>Penalties: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Load in the claws</source>
        <translation>Load in the claws</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Paused by the instructor</source>
        <translation>Paused by the instructor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overload: a relief valve is open</source>
        <translation>Overload: a relief valve is open</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Too close to a worker (%1 m)</source>
        <translation>Too close to a worker (%1 m)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Clearance %1 m</source>
        <translation>Clearance %1 m</translation>
    </message>
</context>
<context>
    <name>studio::CalibrationWizard</name>
    <message>
        <location filename="../ide/studio/station/calibration_wizard.cpp" line="+70" />
        <source>Axis %1</source>
        <translation>Axis %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Calibrate %1 of %2</source>
        <translation>Calibrate %1 of %2</translation>
    </message>
    <message>
        <location line="+68" />
        <source>Leave the lever at rest</source>
        <translation>Leave the lever at rest</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Let go of the lever (or stick) and leave it where it rests by itself. Its reading over the next moments is the centre of the channel.</source>
        <translation>Let go of the lever (or stick) and leave it where it rests by itself. Its reading over the next moments is the centre of the channel.</translation>
    </message>
    <message>
        <location line="+274" />
        <source>Capturing… %p%</source>
        <translation>Capturing… %p%</translation>
    </message>
    <message>
        <location line="-272" />
        <source>Capture again</source>
        <translation>Capture again</translation>
    </message>
    <message>
        <location line="-69" />
        <source>&lt; &amp;Back</source>
        <translation>&lt; &amp;Back</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Next &gt;</source>
        <translation>&amp;Next &gt;</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Finish</source>
        <translation>&amp;Finish</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+67" />
        <source>Forget these readings and capture the rest position anew</source>
        <translation>Forget these readings and capture the rest position anew</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Move the lever to its full travel, both ways</source>
        <translation>Move the lever to its full travel, both ways</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Push the lever slowly all the way to one end, then all the way to the other, and let it come back to rest. A lever that only moves one way (a trigger, a pedal) is fine: move it to its end.</source>
        <translation>Push the lever slowly all the way to one end, then all the way to the other, and let it come back to rest. A lever that only moves one way (a trigger, a pedal) is fine: move it to its end.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The reading now; the red marks are the farthest seen each way</source>
        <translation>The reading now; the red marks are the farthest seen each way</translation>
    </message>
    <message>
        <location line="+72" />
        <source>Dead band, direction and response</source>
        <translation>Dead band, direction and response</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fraction of the travel below the centre where the output stays 0</source>
        <translation>Fraction of the travel below the centre where the output stays 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Fraction of the travel above the centre where the output stays 0</source>
        <translation>Fraction of the travel above the centre where the output stays 0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dead band below centre:</source>
        <translation>Dead band below centre:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dead band above centre:</source>
        <translation>Dead band above centre:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inverted</source>
        <translation>Inverted</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Pushing the lever towards its maximum reading gives a negative command</source>
        <translation>Pushing the lever towards its maximum reading gives a negative command</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exponential</source>
        <translation>Exponential</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Exponential: finer control near the centre</source>
        <translation>Exponential: finer control near the centre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Response:</source>
        <translation>Response:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>k of y = (e^(k·x) − 1)/(e^k − 1): larger is finer near the centre</source>
        <translation>k of y = (e^(k·x) − 1)/(e^k − 1): larger is finer near the centre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Curve parameter k:</source>
        <translation>Curve parameter k:</translation>
    </message>
    <message>
        <location line="+1" />
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1" />
        <source>off</source>
        <translation>off</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Low-pass cutoff frequency against a noisy pot (0: no filter)</source>
        <translation>Low-pass cutoff frequency against a noisy pot (0: no filter)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Low-pass filter:</source>
        <translation>Low-pass filter:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep this calibration for</source>
        <translation>Keep this calibration for</translation>
    </message>
    <message>
        <location line="+1" />
        <source>This device only (%1)</source>
        <translation>This device only (%1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Only this very device uses it</source>
        <translation>Only this very device uses it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Any %1</source>
        <translation>Any %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Every device of this kind uses it, so the profile works with another one of the same make (profile key “%1”)</source>
        <translation>Every device of this kind uses it, so the profile works with another one of the same make (profile key “%1”)</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Raw:</source>
        <translation>Raw:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Calibrated:</source>
        <translation>Calibrated:</translation>
    </message>
    <message>
        <location line="+45" />
        <source>%1 is not there any more.</source>
        <translation>%1 is not there any more.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: %2 — waiting for it.</source>
        <translation>%1: %2 — waiting for it.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 has no channel %2.</source>
        <translation>%1 has no channel %2.</translation>
    </message>
    <message>
        <location line="+71" />
        <source>Captured</source>
        <translation>Captured</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Reading: %1</source>
        <translation>Reading: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Waiting for readings…</source>
        <translation>Waiting for readings…</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Reading: %1    Centre: %2    Spread: %3 (%4 % of the travel)</source>
        <translation>Reading: %1    Centre: %2    Spread: %3 (%4 % of the travel)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The reading moves while the lever rests: a noisy pot or a loose wire? A dead band or the low-pass filter will hide some of it.</source>
        <translation>The reading moves while the lever rests: a noisy pot or a loose wire? A dead band or the low-pass filter will hide some of it.</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Reading: %1    Centre: %2    Seen: %3 … %4</source>
        <translation>Reading: %1    Centre: %2    Seen: %3 … %4</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Enough travel seen. Keep moving to reach the very ends, then press Next.</source>
        <translation>Enough travel seen. Keep moving to reach the very ends, then press Next.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Captured: minimum %1, centre %2, maximum %3.</source>
        <translation>Captured: minimum %1, centre %2, maximum %3.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>One-sided: the output goes from 0 to 1.</source>
        <translation>One-sided: the output goes from 0 to 1.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Raw %1 → %2</source>
        <translation>Raw %1 → %2</translation>
    </message>
</context>
<context>
    <name>studio::ChannelPanel</name>
    <message>
        <location filename="../ide/studio/station/channel_bars.cpp" line="+228" />
        <location line="+23" />
        <source>No device selected</source>
        <translation>No device selected</translation>
    </message>
    <message>
        <location line="-24" />
        <source>Buttons</source>
        <translation>Buttons</translation>
    </message>
    <message>
        <location line="-2" />
        <source>Keys are digital: a key gives its drive the full command (−1, 0 or +1) at once, so there is nothing to calibrate. A ramp eases each key's command in and out instead.</source>
        <translation>Keys are digital: a key gives its drive the full command (−1, 0 or +1) at once, so there is nothing to calibrate. A ramp eases each key's command in and out instead.</translation>
    </message>
    <message>
        <location line="+36" />
        <source>%1: no channels (yet)</source>
        <translation>%1: no channels (yet)</translation>
    </message>
    <message numerus="yes">
        <location line="+2" />
        <source>%1: %n channel(s)</source>
        <translation>
            <numerusform>%1: %n channel</numerusform>
            <numerusform>%1: %n channels</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Channel</source>
        <translation>Channel</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Raw reading</source>
        <translation>Raw reading</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Calibrated</source>
        <translation>Calibrated</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ramp</source>
        <translation>Ramp</translation>
    </message>
    <message>
        <location line="+29" />
        <location line="+91" />
        <source>not calibrated</source>
        <translation>not calibrated</translation>
    </message>
    <message>
        <location line="-84" />
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>at once</source>
        <translation>at once</translation>
    </message>
    <message>
        <location line="+1" />
        <source>How long a key takes to open its valve fully (and to close it again): 0 gives the full command at once</source>
        <translation>How long a key takes to open its valve fully (and to close it again): 0 gives the full command at once</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Calibrate…</source>
        <translation>Calibrate…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Capture this channel's centre and travel, and set its dead band and curve</source>
        <translation>Capture this channel's centre and travel, and set its dead band and curve</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Button %1: %2</source>
        <translation>Button %1: %2</translation>
    </message>
    <message>
        <location line="+52" />
        <source>out of range</source>
        <translation>out of range</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The reading is beyond the calibrated range: the pot slipped, a wire is loose, or the calibration is stale. Calibrate again.</source>
        <translation>The reading is beyond the calibrated range: the pot slipped, a wire is loose, or the calibration is stale. Calibrate again.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The device's nominal range is in use until this channel is calibrated</source>
        <translation>The device's nominal range is in use until this channel is calibrated</translation>
    </message>
</context>
<context>
    <name>studio::CourseScreen</name>
    <message>
        <location filename="../ide/studio/train/course_screen.cpp" line="+25" />
        <source>Training course</source>
        <translation>Training course</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Operator:</source>
        <translation>Operator:</translation>
    </message>
    <message>
        <location line="+8" />
        <source>name or number</source>
        <translation>name or number</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Records</source>
        <translation>Records</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The trainee records: operators, attempts, progress (for the trainer).</source>
        <translation>The trainee records: operators, attempts, progress (for the trainer).</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Open</source>
        <translation>Open</translation>
    </message>
    <message>
        <location line="+47" />
        <source>Level %1 — %2</source>
        <translation>Level %1 — %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>(cannot be used)</source>
        <translation>(cannot be used)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>This tutorial cannot be loaded.</source>
        <translation>This tutorial cannot be loaded.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>(locked: pass the level before)</source>
        <translation>(locked: pass the level before)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Pass every stage of the level before to unlock this one.</source>
        <translation>Pass every stage of the level before to unlock this one.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>best %1 of 100</source>
        <translation>best %1 of 100</translation>
    </message>
</context>
<context>
    <name>studio::CurvePlot</name>
    <message>
        <location filename="../ide/studio/station/curve_plot.cpp" line="+118" />
        <source>raw reading → output (shaded: dead band)</source>
        <translation>raw reading → output (shaded: dead band)</translation>
    </message>
</context>
<context>
    <name>studio::DebriefScreen</name>
    <message>
        <location filename="../ide/studio/train/debrief_screen.cpp" line="+58" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+97" />
        <location line="+24" />
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="-24" />
        <location line="+24" />
        <location line="+24" />
        <location line="+23" />
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <location line="-70" />
        <source>Events</source>
        <translation>Events</translation>
    </message>
    <message>
        <location line="+1" />
        <source>You and the expert</source>
        <translation>You and the expert</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measure</source>
        <translation>Measure</translation>
    </message>
    <message>
        <location line="+0" />
        <source>You</source>
        <translation>You</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Expert</source>
        <translation>Expert</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the result</source>
        <translation>Back to the result</translation>
    </message>
    <message>
        <location line="+56" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+40" />
        <source>%1 s — %2</source>
        <translation>%1 s — %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>No events.</source>
        <translation>No events.</translation>
    </message>
    <message>
        <location line="+44" />
        <source>Force of %1</source>
        <translation>Force of %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>No drive force</source>
        <translation>No drive force</translation>
    </message>
    <message>
        <location line="+1" />
        <source>kN</source>
        <translation>kN</translation>
    </message>
    <message>
        <location line="+0" />
        <source>kN·m</source>
        <translation>kN·m</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Relief valves open</source>
        <translation>Relief valves open</translation>
    </message>
    <message>
        <location line="+0" />
        <source>valves</source>
        <translation>valves</translation>
    </message>
    <message>
        <location line="+15" />
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Path length [m]</source>
        <translation>Path length [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Overshoot [m]</source>
        <translation>Overshoot [m]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RMS jerk [m/s³]</source>
        <translation>RMS jerk [m/s³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score</source>
        <translation>Score</translation>
    </message>
    <message>
        <location line="+8" />
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <location line="+0" />
        <source>none</source>
        <translation>none</translation>
    </message>
</context>
<context>
    <name>studio::DisplayFeed</name>
    <message>
        <location filename="../ide/studio/centre/display_feed.cpp" line="+174" />
        <source>The station announced no usable model name (“%1”).</source>
        <translation>The station announced no usable model name (“%1”).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The station's model “%1” is not installed on this computer (%2).</source>
        <translation>The station's model “%1” is not installed on this computer (%2).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The model file %1 cannot be read.</source>
        <translation>The model file %1 cannot be read.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The station runs another version of the model “%1” than the one installed on this computer (%2): install the same model files on both computers.</source>
        <translation>The station runs another version of the model “%1” than the one installed on this computer (%2): install the same model files on both computers.</translation>
    </message>
    <message>
        <location line="+31" />
        <source>The station's model %1 has errors on this computer: %2</source>
        <translation>The station's model %1 has errors on this computer: %2</translation>
    </message>
</context>
<context>
    <name>studio::DisplayView</name>
    <message>
        <location filename="../ide/studio/centre/display_view.cpp" line="+114" />
        <source>Waiting for station %1…</source>
        <translation>Waiting for station %1…</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Station %1 is silent: no state for %2 s.</source>
        <translation>Station %1 is silent: no state for %2 s.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Station %1 has left the centre.</source>
        <translation>Station %1 has left the centre.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Waiting for station %1 to announce its model…</source>
        <translation>Waiting for station %1 to announce its model…</translation>
    </message>
</context>
<context>
    <name>studio::DisplayWindow</name>
    <message>
        <location filename="../ide/studio/centre/display_window.cpp" line="+29" />
        <source>This display has no centre key (--centre-key FILE): it cannot check what the stations send, so it shows nothing.</source>
        <translation>This display has no centre key (--centre-key FILE): it cannot check what the stations send, so it shows nothing.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>This display's key is station %1's: it cannot check what station %2 sends, so it shows nothing. Give it station %2's key or the centre's key.</source>
        <translation>This display's key is station %1's: it cannot check what station %2 sends, so it shows nothing. Give it station %2's key or the centre's key.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>This display cannot join the training centre's network (DDS domain %1): %2</source>
        <translation>This display cannot join the training centre's network (DDS domain %1): %2</translation>
    </message>
    <message>
        <location line="+65" />
        <source>left screen</source>
        <translation>left screen</translation>
    </message>
    <message>
        <location line="+0" />
        <source>centre screen</source>
        <translation>centre screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>right screen</source>
        <translation>right screen</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob display: station %1, %2</source>
        <translation>Padrob display: station %1, %2</translation>
    </message>
</context>
<context>
    <name>studio::EditorPanel</name>
    <message>
        <location filename="../ide/studio/editor/editor_panel.cpp" line="+119" />
        <source>Apply</source>
        <translation>Apply</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Use this model in the 3D view and the simulation</source>
        <translation>Use this model in the 3D view and the simulation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Reload</source>
        <translation>Reload</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Read the file again (your unsaved edits stay in Undo)</source>
        <translation>Read the file again (your unsaved edits stay in Undo)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keep my text</source>
        <translation>Keep my text</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Go on with the text in the editor; saving writes it over the file</source>
        <translation>Go on with the text in the editor; saving writes it over the file</translation>
    </message>
    <message>
        <location line="+2" />
        <source>“%1” changed on disk, and the editor has unsaved changes.</source>
        <translation>“%1” changed on disk, and the editor has unsaved changes.</translation>
    </message>
    <message numerus="yes">
        <location line="+179" />
        <source>%1, %n warning(s)</source>
        <comment>the %1 is "%n error(s)"</comment>
        <translation>
            <numerusform>%1, %n warning</numerusform>
            <numerusform>%1, %n warnings</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+20" />
        <source>Not applied: the model has %n error(s). The model applied before stays in use.</source>
        <translation>
            <numerusform>Not applied: the model has %n error. The model applied before stays in use.</numerusform>
            <numerusform>Not applied: the model has %n errors. The model applied before stays in use.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>Not applied: the model could not be compiled.</source>
        <translation>Not applied: the model could not be compiled.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Checking…</source>
        <translation>Checking…</translation>
    </message>
    <message>
        <location line="-24" />
        <location line="+28" />
        <source>No problems</source>
        <translation>No problems</translation>
    </message>
    <message numerus="yes">
        <location line="-31" />
        <location line="+1" />
        <source>%n error(s)</source>
        <translation>
            <numerusform>%n error</numerusform>
            <numerusform>%n errors</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n warning(s)</source>
        <translation>
            <numerusform>%n warning</numerusform>
            <numerusform>%n warnings</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::FrameBench</name>
    <message>
        <location filename="../ide/studio/app/frame_bench.cpp" line="+196" />
        <source>Cannot read the model %1.</source>
        <translation>Cannot read the model %1.</translation>
    </message>
    <message>
        <location line="+38" />
        <source>The model %1 was not drawn (does it have errors?).</source>
        <translation>The model %1 was not drawn (does it have errors?).</translation>
    </message>
    <message>
        <location line="+35" />
        <source>The simulation does not run.</source>
        <translation>The simulation does not run.</translation>
    </message>
    <message numerus="yes">
        <location line="+21" />
        <source>The %n view(s) do not draw.</source>
        <translation>
            <numerusform>The view does not draw.</numerusform>
            <numerusform>The %n views do not draw.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+175" />
        <source>No model was drawn (does it have errors?).</source>
        <translation>No model was drawn (does it have errors?).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Cannot write %1.</source>
        <translation>Cannot write %1.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 drawn; the window saved to %2.</source>
        <translation>%1 drawn; the window saved to %2.</translation>
    </message>
</context>
<context>
    <name>studio::GettingStarted</name>
    <message>
        <location filename="../ide/studio/app/getting_started.cpp" line="+57" />
        <source>Getting started</source>
        <translation>Getting started</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Run and pause</source>
        <translation>Run and pause</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulation ▸ Run (%1) starts the machine, Pause (%2) holds it; Reset puts it back at the start.</source>
        <translation>Simulation ▸ Run (%1) starts the machine, Pause (%2) holds it; Reset puts it back at the start.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Keys</source>
        <translation>Keys</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Click the 3D view, then hold a key to open a valve: the first key of a pair (%1, %2, …) drives one way, the second the other. Simulation ▸ Keyboard Controls lists which drive each pair moves; in Train, the start screen and the attempt name the keys and levers of each stage.</source>
        <translation>Click the 3D view, then hold a key to open a valve: the first key of a pair (%1, %2, …) drives one way, the second the other. Simulation ▸ Keyboard Controls lists which drive each pair moves; in Train, the start screen and the attempt name the keys and levers of each stage.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Mouse in the 3D view</source>
        <translation>Mouse in the 3D view</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left drag orbits, middle drag or Shift + left drag pans, the wheel zooms, a double click frames the model.</source>
        <translation>Left drag orbits, middle drag or Shift + left drag pans, the wheel zooms, a double click frames the model.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Help ▸ Getting Started shows this again.</source>
        <translation>Help ▸ Getting Started shows this again.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Got it</source>
        <translation>Got it</translation>
    </message>
</context>
<context>
    <name>studio::HydraulicPanel</name>
    <message>
        <location filename="../ide/studio/sim/hydraulic_panel.cpp" line="+166" />
        <location line="+41" />
        <source>Hydraulics</source>
        <translation>Hydraulics</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Pump %1</source>
        <translation>Pump %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Pump %1: %2</source>
        <translation>Pump %1: %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Supply pressure: %1 of %2 MPa</source>
        <translation>Supply pressure: %1 of %2 MPa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delivered flow: %1 of %2 L/min</source>
        <translation>Delivered flow: %1 of %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Demand of the open sections: %1 L/min</source>
        <translation>Demand of the open sections: %1 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Saturated: the sections want more flow than the pump gives.</source>
        <translation>Saturated: the sections want more flow than the pump gives.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>Spool: %1 %</source>
        <translation>Spool: %1 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A: %1 MPa, flow in %2 L/min</source>
        <translation>Chamber A: %1 MPa, flow in %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B: %1 MPa, flow in %2 L/min</source>
        <translation>Chamber B: %1 MPa, flow in %2 L/min</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Relief setting: %1 MPa</source>
        <translation>Relief setting: %1 MPa</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A is at the relief setting.</source>
        <translation>Chamber A is at the relief setting.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B is at the relief setting.</source>
        <translation>Chamber B is at the relief setting.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber A cavitates.</source>
        <translation>Chamber A cavitates.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Chamber B cavitates.</source>
        <translation>Chamber B cavitates.</translation>
    </message>
    <message>
        <location line="+54" />
        <source>This model has no fluid-power drives.</source>
        <translation>This model has no fluid-power drives.</translation>
    </message>
    <message>
        <location line="+0" />
        <source>No model is running.</source>
        <translation>No model is running.</translation>
    </message>
    <message>
        <location line="+30" />
        <source>supply %1 of %2 MPa</source>
        <translation>supply %1 of %2 MPa</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+41" />
        <location line="+1" />
        <source>%1 MPa</source>
        <translation>%1 MPa</translation>
    </message>
    <message>
        <location line="-40" />
        <source>flow %1 of %2 L/min, saturated</source>
        <translation>flow %1 of %2 L/min, saturated</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 L/min, saturated</source>
        <translation>%1 L/min, saturated</translation>
    </message>
    <message>
        <location line="+0" />
        <source>saturated</source>
        <translation>saturated</translation>
    </message>
    <message>
        <location line="+1" />
        <source>flow %1 of %2 L/min</source>
        <translation>flow %1 of %2 L/min</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 L/min</source>
        <translation>%1 L/min</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Spool</source>
        <translation>Spool</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Chamber A</source>
        <translation>Chamber A</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Chamber B</source>
        <translation>Chamber B</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Valve section</source>
        <translation>Valve section</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 MPa, cavitation</source>
        <translation>%1 MPa, cavitation</translation>
    </message>
    <message>
        <location line="+0" />
        <source>cavitation</source>
        <translation>cavitation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 MPa, relief</source>
        <translation>%1 MPa, relief</translation>
    </message>
</context>
<context>
    <name>studio::InertiaDialog</name>
    <message>
        <location filename="../ide/studio/dialogs/inertia_dialog.cpp" line="+72" />
        <source>n/a (file: 0)</source>
        <translation>n/a (file: 0)</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+4" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+155" />
        <source>Inertia calculator</source>
        <translation>Inertia calculator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Body:</source>
        <translation>Body:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The solids of a body are its graphics (G) with MASS or RHO. Edits in this table only change this calculation: the G lines in the file are not changed. Only the body's B line can be written back, with the button below.</source>
        <translation>The solids of a body are its graphics (G) with MASS or RHO. Edits in this table only change this calculation: the G lines in the file are not changed. Only the body's B line can be written back, with the button below.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Graphic</source>
        <translation>Graphic</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Shape</source>
        <translation>Shape</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Dimensions [m]</source>
        <translation>Dimensions [m]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>POS [m]</source>
        <translation>POS [m]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>AXIS</source>
        <translation>AXIS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ROT [axis, °]</source>
        <translation>ROT [axis, °]</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Density or mass</source>
        <translation>Density or mass</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Solid's mass [kg]</source>
        <translation>Solid's mass [kg]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH</source>
        <translation>BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH</translation>
    </message>
    <message>
        <location line="+2" />
        <source>BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L; ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; MESH "file" [SCALE s]</source>
        <translation>BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L; ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; MESH "file" [SCALE s]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RHO in kg/m³, or MASS in kg</source>
        <translation>RHO in kg/m³, or MASS in kg</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Computed (body axes, about the centre of mass)</source>
        <translation>Computed (body axes, about the centre of mass)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>I = [[Ixx Ixy Ixz] [Ixy Iyy Iyz] [Ixz Iyz Izz]], Ixy = −∫xy dm</source>
        <translation>I = [[Ixx Ixy Ixz] [Ixy Iyy Iyz] [Ixz Iyz Izz]], Ixy = −∫xy dm</translation>
    </message>
    <message>
        <location line="+18" />
        <source>B %1 (no solids)</source>
        <translation>B %1 (no solids)</translation>
    </message>
    <message>
        <location line="+0" />
        <source>B %1  %2 (no solids)</source>
        <translation>B %1  %2 (no solids)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B %1 (solids: %2)</source>
        <translation>B %1 (solids: %2)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B %1  %2 (solids: %3)</source>
        <translation>B %1  %2 (solids: %3)</translation>
    </message>
    <message>
        <location line="-23" />
        <source>Mass:</source>
        <translation>Mass:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Centre of mass:</source>
        <translation>Centre of mass:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Inertia tensor [kg·m²]:</source>
        <translation>Inertia tensor [kg·m²]:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Principal moments:</source>
        <translation>Principal moments:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Against the file:</source>
        <translation>Against the file:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>B line</source>
        <translation>B line</translation>
    </message>
    <message>
        <location line="+1" />
        <source>In the file:</source>
        <translation>In the file:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Computed:</source>
        <translation>Computed:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Replace B line in editor</source>
        <translation>Replace B line in editor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Writes the computed B line into the editor (one undo step); the G lines stay as they are</source>
        <translation>Writes the computed B line into the editor (one undo step); the G lines stay as they are</translation>
    </message>
    <message>
        <location line="+6" />
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location line="+14" />
        <source>G %1</source>
        <translation>G %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>line %1</source>
        <translation>line %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>RHO [kg/m³]</source>
        <translation>RHO [kg/m³]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>MASS [kg]</source>
        <translation>MASS [kg]</translation>
    </message>
    <message>
        <location line="+159" />
        <source>Error: %1</source>
        <translation>Error: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning: %1</source>
        <translation>Warning: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Error: %1 — %2</source>
        <translation>Error: %1 — %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning: %1 — %2</source>
        <translation>Warning: %1 — %2</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Body %1 has no solids: give some of its graphics MASS or RHO (e.g. G 1 B %1 BOX 0.2 0.2 0.2 RHO 7850).</source>
        <translation>Body %1 has no solids: give some of its graphics MASS or RHO (e.g. G 1 B %1 BOX 0.2 0.2 0.2 RHO 7850).</translation>
    </message>
    <message>
        <location line="+6" />
        <source>The solids have no mass.</source>
        <translation>The solids have no mass.</translation>
    </message>
    <message>
        <location line="+37" />
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(%1, %2, %3) m</source>
        <translation>(%1, %2, %3) m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1, %2, %3 kg·m²</source>
        <translation>%1, %2, %3 kg·m²</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 kg·m² about (%2, %3, %4)</source>
        <translation>%1 kg·m² about (%2, %3, %4)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>m %1, Ixx %2, Iyy %3, Izz %4</source>
        <translation>m %1, Ixx %2, Iyy %3, Izz %4</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the file's B line has no mass</source>
        <translation>the file's B line has no mass</translation>
    </message>
</context>
<context>
    <name>studio::InstructorWindow</name>
    <message>
        <location filename="../ide/studio/centre/instructor_window.cpp" line="+269" />
        <source>up</source>
        <translation>up</translation>
    </message>
    <message>
        <location line="+0" />
        <source>silent</source>
        <translation>silent</translation>
    </message>
    <message>
        <location line="+0" />
        <source>left</source>
        <translation>left</translation>
    </message>
    <message>
        <location line="+5" />
        <source>idle</source>
        <translation>idle</translation>
    </message>
    <message>
        <location line="+1" />
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>paused</source>
        <translation>paused</translation>
    </message>
    <message>
        <location line="+1" />
        <source>ended</source>
        <translation>ended</translation>
    </message>
    <message>
        <location line="+4" />
        <source>overload</source>
        <translation>overload</translation>
    </message>
    <message>
        <location line="+1" />
        <source>near a worker</source>
        <translation>near a worker</translation>
    </message>
    <message>
        <location line="+1" />
        <source>near the scene</source>
        <translation>near the scene</translation>
    </message>
    <message>
        <location line="+1" />
        <source>records offline</source>
        <translation>records offline</translation>
    </message>
    <message>
        <location line="+1" />
        <source>records kept aside (journal refuses writes)</source>
        <translation>records kept aside (journal refuses writes)</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+307" />
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="-295" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1/%2</source>
        <translation>%1/%2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location line="+33" />
        <source>%1 s  %2</source>
        <translation>%1 s  %2</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Padrob instructor</source>
        <translation>Padrob instructor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Presence</source>
        <translation>Presence</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Tutorial</source>
        <translation>Tutorial</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Operator</source>
        <translation>Operator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Time</source>
        <translation>Time</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Score</source>
        <translation>Score</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Goals</source>
        <translation>Goals</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warnings and faults</source>
        <translation>Warnings and faults</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Latency</source>
        <translation>Latency</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start…</source>
        <translation>Start…</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+48" />
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Resume</source>
        <translation>Resume</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Reset</source>
        <translation>Reset</translation>
    </message>
    <message>
        <location line="-47" />
        <location line="+48" />
        <source>Stop</source>
        <translation>Stop</translation>
    </message>
    <message>
        <location line="-47" />
        <source>Inject fault…</source>
        <translation>Inject fault…</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+48" />
        <source>Clear fault</source>
        <translation>Clear fault</translation>
    </message>
    <message>
        <location line="-47" />
        <source>Events</source>
        <translation>Events</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Events of %1 (latest last)</source>
        <translation>Events of %1 (latest last)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cannot join the training centre's network: %1</source>
        <translation>Cannot join the training centre's network: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Centre key %1: commands are signed with it, and what the stations say is checked against it.</source>
        <translation>Centre key %1: commands are signed with it, and what the stations say is checked against it.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The centre's key cannot be used (%1): what the stations say cannot be checked, so none of it is shown, and no command can be sent.</source>
        <translation>The centre's key cannot be used (%1): what the stations say cannot be checked, so none of it is shown, and no command can be sent.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Without the centre's key (--centre-key FILE) what the stations say cannot be checked, so none of it is shown, and no command can be sent.</source>
        <translation>Without the centre's key (--centre-key FILE) what the stations say cannot be checked, so none of it is shown, and no command can be sent.</translation>
    </message>
    <message>
        <location line="+43" />
        <source>the station has already taken this very command (a replay).</source>
        <translation>the station has already taken this very command (a replay).</translation>
    </message>
    <message>
        <location line="+1" />
        <source>a field of the command is longer than the centre allows.</source>
        <translation>a field of the command is longer than the centre allows.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station has taken too many commands in the last 30 seconds; try again shortly.</source>
        <translation>the station has taken too many commands in the last 30 seconds; try again shortly.</translation>
    </message>
    <message>
        <location line="-37" />
        <source>Not connected to the training centre's network.</source>
        <translation>Not connected to the training centre's network.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Commands need the centre's key: start padrob-studio with --centre-key FILE.</source>
        <translation>Commands need the centre's key: start padrob-studio with --centre-key FILE.</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+89" />
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="-84" />
        <source>Inject fault</source>
        <translation>Inject fault</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the command was not signed with the key this station has.</source>
        <translation>the command was not signed with the key this station has.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the command was too old when it arrived: check that the computers' clocks agree.</source>
        <translation>the command was too old when it arrived: check that the computers' clocks agree.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the station has no centre key and takes no commands.</source>
        <translation>the station has no centre key and takes no commands.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>no attempt is running on the station.</source>
        <translation>no attempt is running on the station.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the attempt is not paused.</source>
        <translation>the attempt is not paused.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not have that tutorial.</source>
        <translation>the station does not have that tutorial.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not know that fault.</source>
        <translation>the station does not know that fault.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the station does not know that command.</source>
        <translation>the station does not know that command.</translation>
    </message>
    <message>
        <location line="+21" />
        <source>%1 on %2</source>
        <translation>%1 on %2</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1: sent, waiting for the station…</source>
        <translation>%1: sent, waiting for the station…</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: could not be sent.</source>
        <translation>%1: could not be sent.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1: could not be sent (%2).</source>
        <translation>%1: could not be sent (%2).</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1: done.</source>
        <translation>%1: done.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1: refused, %2</source>
        <translation>%1: refused, %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1: no reply from the station in 5 s.</source>
        <translation>%1: no reply from the station in 5 s.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Start a tutorial on %1</source>
        <translation>Start a tutorial on %1</translation>
    </message>
    <message>
        <location line="+8" />
        <source>guest</source>
        <translation>guest</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tutorial:</source>
        <translation>Tutorial:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operator code:</source>
        <translation>Operator code:</translation>
    </message>
    <message>
        <location line="+19" />
        <source>Inject a fault on %1</source>
        <translation>Inject a fault on %1</translation>
    </message>
    <message>
        <location line="+30" />
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Fault:</source>
        <translation>Fault:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Drive:</source>
        <translation>Drive:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Valve opening (−1 … 1):</source>
        <translation>Valve opening (−1 … 1):</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Where the worker walks to (x, y, z):</source>
        <translation>Where the worker walks to (x, y, z):</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Inject</source>
        <translation>Inject</translation>
    </message>
</context>
<context>
    <name>studio::JointSliders</name>
    <message>
        <location filename="../ide/studio/tree/joint_sliders.cpp" line="+77" />
        <source>Reset pose</source>
        <translation>Reset pose</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the model's initial coordinates</source>
        <translation>Back to the model's initial coordinates</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No model</source>
        <translation>No model</translation>
    </message>
    <message>
        <location line="+5" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>C %1  %2</source>
        <translation>C %1  %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1, limits %2</source>
        <translation>%1, limits %2</translation>
    </message>
    <message>
        <location line="+6" />
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location line="+0" />
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location line="-13" />
        <source>The model has no degrees of freedom to pose.</source>
        <translation>The model has no degrees of freedom to pose.</translation>
    </message>
    <message>
        <location line="+232" />
        <source>C %1 cannot reach the length %2: kept the last pose.</source>
        <translation>C %1 cannot reach the length %2: kept the last pose.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>The loops cannot close with C %1 at %2: the pose stops at %3, the last one that closes.</source>
        <translation>The loops cannot close with C %1 at %2: the pose stops at %3, the last one that closes.</translation>
    </message>
</context>
<context>
    <name>studio::JointText</name>
    <message>
        <location filename="../ide/studio/tree/joint_text.cpp" line="+27" />
        <location line="+31" />
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location line="-30" />
        <location line="+31" />
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <location line="-27" />
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location line="+0" />
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+14" />
        <source>revolute</source>
        <translation>revolute</translation>
    </message>
    <message>
        <location line="+1" />
        <source>pivoted actuator</source>
        <translation>pivoted actuator</translation>
    </message>
    <message>
        <location line="+1" />
        <source>prismatic</source>
        <translation>prismatic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>free body</source>
        <translation>free body</translation>
    </message>
    <message>
        <location line="+5" />
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>°</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>≥ %1</source>
        <translation>≥ %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>≤ %1</source>
        <translation>≤ %1</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+29" />
        <source>unlimited</source>
        <translation>unlimited</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 MN·m</source>
        <translation>%1 MN·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 MN</source>
        <translation>%1 MN</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 kN·m</source>
        <translation>%1 kN·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 kN</source>
        <translation>%1 kN</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 N·m</source>
        <translation>%1 N·m</translation>
    </message>
    <message>
        <location line="+0" />
        <source>%1 N</source>
        <translation>%1 N</translation>
    </message>
    <message>
        <location line="+9" />
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>+%1/-%2 %3</source>
        <translation>+%1/-%2 %3</translation>
    </message>
    <message>
        <location line="+4" />
        <source>+%1/-%2</source>
        <translation>+%1/-%2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>hydraulic %1, relief %2</source>
        <translation>hydraulic %1, relief %2</translation>
    </message>
    <message>
        <location line="+2" />
        <source>hydraulic %1</source>
        <translation>hydraulic %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>motor T0 %1, W0 %2 rad/s</source>
        <translation>motor T0 %1, W0 %2 rad/s</translation>
    </message>
    <message>
        <location line="+3" />
        <source>pneumatic %1</source>
        <translation>pneumatic %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>servo KP %1, KI %2, KD %3</source>
        <translation>servo KP %1, KI %2, KD %3</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1, FMAX %2</source>
        <translation>%1, FMAX %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>massless</source>
        <translation>massless</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
</context>
<context>
    <name>studio::KeyboardInput</name>
    <message>
        <location filename="../ide/studio/sim/keyboard_input.cpp" line="+103" />
        <source>%1 — C %2</source>
        <translation>%1 — C %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 — C %2 %3</source>
        <translation>%1 — C %2 %3</translation>
    </message>
</context>
<context>
    <name>studio::MainWindow</name>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+155" />
        <source>Export</source>
        <translation>Export</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+240" />
        <location line="+2" />
        <source>Model</source>
        <translation>Model</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Joints</source>
        <translation>Joints</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Editor</source>
        <translation>Editor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Plots</source>
        <translation>Plots</translation>
    </message>
    <message>
        <location line="-5" />
        <source>Train</source>
        <translation>Train</translation>
    </message>
    <message>
        <location line="-1" />
        <source>Workspaces</source>
        <translation>Workspaces</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+201" />
        <source>Leave Trainer Mode</source>
        <translation>Leave Trainer Mode</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Trainer's PIN:</source>
        <translation>Trainer's PIN:</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+16" />
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;New</source>
        <translation>&amp;New</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Open…</source>
        <translation>&amp;Open…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Save</source>
        <translation>&amp;Save</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save &amp;As…</source>
        <translation>Save &amp;As…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Recent Files</source>
        <translation>&amp;Recent Files</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Examples</source>
        <translation>&amp;Examples</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Quit</source>
        <translation>&amp;Quit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Edit</source>
        <translation>&amp;Edit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Undo</source>
        <translation>&amp;Undo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Redo</source>
        <translation>&amp;Redo</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Apply Model</source>
        <translation>&amp;Apply Model</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Inertia Calculator…</source>
        <translation>&amp;Inertia Calculator…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;View</source>
        <translation>&amp;View</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Schematic</source>
        <translation>&amp;Schematic</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Dressed</source>
        <translation>&amp;Dressed</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Both</source>
        <translation>&amp;Both</translation>
    </message>
    <message>
        <location line="+3" />
        <source>&amp;Camera</source>
        <translation>&amp;Camera</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Fit All</source>
        <translation>&amp;Fit All</translation>
    </message>
    <message>
        <location line="+1" />
        <source>S&amp;cene</source>
        <translation>S&amp;cene</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Load…</source>
        <translation>&amp;Load…</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+43" />
        <location filename="../ide/studio/app/main_window_menus.cpp" line="-175" />
        <source>Load Scene</source>
        <translation>Load Scene</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+176" />
        <source>&amp;None</source>
        <translation>&amp;None</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Body &amp;Frames</source>
        <translation>Body &amp;Frames</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Screens</source>
        <translation>&amp;Screens</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>%n Screen(s)</source>
        <translation>
            <numerusform>%n Screen</numerusform>
            <numerusform>%n Screens</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1" />
        <source>Three &amp;Windows (three monitors)</source>
        <translation>Three &amp;Windows (three monitors)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Run</source>
        <translation>&amp;Run</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Step</source>
        <translation>&amp;Step</translation>
    </message>
    <message>
        <location line="+1" />
        <source>R&amp;eset</source>
        <translation>R&amp;eset</translation>
    </message>
    <message>
        <location line="+1" />
        <source>S&amp;peed</source>
        <translation>S&amp;peed</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;Keyboard Controls…</source>
        <translation>&amp;Keyboard Controls…</translation>
    </message>
    <message>
        <location line="+17" />
        <source>&amp;Getting Started</source>
        <translation>&amp;Getting Started</translation>
    </message>
    <message>
        <location line="+22" />
        <source>+</source>
        <translation>+</translation>
    </message>
    <message>
        <location line="+0" />
        <source>−</source>
        <translation>−</translation>
    </message>
    <message>
        <location line="+4" />
        <source>turns +</source>
        <comment>a revolute joint's angle grows</comment>
        <translation>turns +</translation>
    </message>
    <message>
        <location line="+1" />
        <source>turns −</source>
        <comment>a revolute joint's angle shrinks</comment>
        <translation>turns −</translation>
    </message>
    <message>
        <location line="+3" />
        <source>cylinder out</source>
        <comment>a T 1 joint's actuator lengthens</comment>
        <translation>cylinder out</translation>
    </message>
    <message>
        <location line="+1" />
        <source>cylinder in</source>
        <comment>a T 1 joint's actuator shortens</comment>
        <translation>cylinder in</translation>
    </message>
    <message>
        <location line="+3" />
        <source>slides +</source>
        <comment>a prismatic joint's displacement grows</comment>
        <translation>slides +</translation>
    </message>
    <message>
        <location line="+1" />
        <source>slides −</source>
        <comment>a prismatic joint's displacement shrinks</comment>
        <translation>slides −</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 · %3: %4</source>
        <comment>each key of a pair and which way it moves the drive</comment>
        <translation>%1: %2 · %3: %4</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+10" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Left drag</source>
        <translation>Left drag</translation>
    </message>
    <message>
        <location line="+0" />
        <source>orbits around the model</source>
        <translation>orbits around the model</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Middle drag, or Shift + left drag</source>
        <translation>Middle drag, or Shift + left drag</translation>
    </message>
    <message>
        <location line="+0" />
        <source>pans</source>
        <translation>pans</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Wheel</source>
        <translation>Wheel</translation>
    </message>
    <message>
        <location line="+0" />
        <source>zooms towards the cursor</source>
        <translation>zooms towards the cursor</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Double click</source>
        <translation>Double click</translation>
    </message>
    <message>
        <location line="+0" />
        <source>frames the whole model</source>
        <translation>frames the whole model</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Ctrl + left drag on a body</source>
        <translation>Ctrl + left drag on a body</translation>
    </message>
    <message>
        <location line="+1" />
        <source>picks the body and pushes it while the simulation runs (a spring pulls the point you grabbed toward the cursor); release to let go</source>
        <translation>picks the body and pushes it while the simulation runs (a spring pulls the point you grabbed toward the cursor); release to let go</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Keyboard Controls</source>
        <translation>Keyboard Controls</translation>
    </message>
    <message>
        <location line="+2" />
        <source>With the 3D view focused, hold a key to open a valve:</source>
        <translation>With the 3D view focused, hold a key to open a valve:</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Mouse in the 3D view:</source>
        <translation>Mouse in the 3D view:</translation>
    </message>
    <message>
        <location line="-98" />
        <source>&amp;Help</source>
        <translation>&amp;Help</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Model &amp;Language Reference</source>
        <translation>Model &amp;Language Reference</translation>
    </message>
    <message>
        <location line="+2" />
        <source>&amp;About Padrob Studio</source>
        <translation>&amp;About Padrob Studio</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="-16" />
        <location line="+79" />
        <source>Open Model</source>
        <translation>Open Model</translation>
    </message>
    <message>
        <location line="-79" />
        <source>Cannot open %1:
%2</source>
        <translation>Cannot open %1:
%2</translation>
    </message>
    <message>
        <location line="+79" />
        <location filename="../ide/studio/app/main_window_menus.cpp" line="-208" />
        <source>Padrob models (*.pad);;All files (*)</source>
        <translation>Padrob models (*.pad);;All files (*)</translation>
    </message>
    <message numerus="yes">
        <location line="-284" />
        <source>%n attempt(s) kept while the trainee records could not be written were added to them.</source>
        <translation>
            <numerusform>%n attempt kept while the trainee records could not be written was added to them.</numerusform>
            <numerusform>%n attempts kept while the trainee records could not be written were added to them.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2" />
        <source>The trainee records cannot be opened: %1</source>
        <translation>The trainee records cannot be opened: %1</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+139" />
        <source>Hydraulics</source>
        <translation>Hydraulics</translation>
    </message>
    <message>
        <location line="+38" />
        <source>&amp;Contacts</source>
        <translation>&amp;Contacts</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Show where solids touch (models with CONTACT): a red disc at each contact point, its force as an orange arrow</source>
        <translation>Show where solids touch (models with CONTACT): a red disc at each contact point, its force as an orange arrow</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Se&amp;ttings</source>
        <translation>Se&amp;ttings</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&amp;Language</source>
        <translation>&amp;Language</translation>
    </message>
    <message>
        <location line="+1" />
        <source>L&amp;ighting</source>
        <translation>L&amp;ighting</translation>
    </message>
    <message>
        <location line="+4" />
        <source>&amp;Automatic: at the vertices on a software OpenGL, else at every pixel</source>
        <translation>&amp;Automatic: at the vertices on a software OpenGL, else at every pixel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>At every &amp;pixel (finer)</source>
        <translation>At every &amp;pixel (finer)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>At the &amp;vertices (faster)</source>
        <translation>At the &amp;vertices (faster)</translation>
    </message>
    <message>
        <location line="+70" />
        <source>%1 (%2)</source>
        <comment>a drive and its bank</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="+24" />
        <source>Shortcuts (none of them opens a valve):</source>
        <translation>Shortcuts (none of them opens a valve):</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="+220" />
        <source>%1

The 3D view goes on without this scene.</source>
        <translation>%1

The 3D view goes on without this scene.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Scene: %1</source>
        <translation>Scene: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Scene: %1. %2</source>
        <translation>Scene: %1. %2</translation>
    </message>
    <message>
        <location line="+22" />
        <source>The scene used last is not drawn: %1</source>
        <translation>The scene used last is not drawn: %1</translation>
    </message>
    <message>
        <location line="+35" />
        <location line="+14" />
        <source>Save Model</source>
        <translation>Save Model</translation>
    </message>
    <message>
        <location line="-14" />
        <source>The model was not saved:
%1

Use Save As to choose another place.</source>
        <translation>The model was not saved:
%1

Use Save As to choose another place.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Save Model As</source>
        <translation>Save Model As</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Padrob models (*.pad)</source>
        <translation>Padrob models (*.pad)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The model was not saved:
%1</source>
        <translation>The model was not saved:
%1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Unsaved Changes</source>
        <translation>Unsaved Changes</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The model has unsaved changes. Save them?</source>
        <translation>The model has unsaved changes. Save them?</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Untitled</source>
        <translation>Untitled</translation>
    </message>
    <message>
        <location line="+8" />
        <source>an untitled model</source>
        <translation>an untitled model</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Recover Unsaved Changes</source>
        <translation>Recover Unsaved Changes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Padrob Studio was closed with unsaved changes to %1 (recovery copy of %2). Restore them?</source>
        <translation>Padrob Studio was closed with unsaved changes to %1 (recovery copy of %2). Restore them?</translation>
    </message>
    <message>
        <location line="+91" />
        <source>real time ×%1, %2 µs/step</source>
        <translation>real time ×%1, %2 µs/step</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_reload.cpp" line="+52" />
        <source>%1 was deleted or moved on disk; the text in the editor is kept — save it to write it again.</source>
        <translation>%1 was deleted or moved on disk; the text in the editor is kept — save it to write it again.</translation>
    </message>
    <message>
        <location line="+31" />
        <source>%1 changed on disk and was reloaded; the pose is kept.</source>
        <translation>%1 changed on disk and was reloaded; the pose is kept.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 changed on disk and was reloaded; its joints changed, so it starts from the initial pose.</source>
        <translation>%1 changed on disk and was reloaded; its joints changed, so it starts from the initial pose.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>The editor has changes that are not applied: the 3D view, the tree and the plots show the model applied before. Apply (Ctrl+Return) to use them, or Revert.</source>
        <translation>The editor has changes that are not applied: the 3D view, the tree and the plots show the model applied before. Apply (Ctrl+Return) to use them, or Revert.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Apply</source>
        <translation>Apply</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Revert</source>
        <translation>Revert</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Put the applied model's text back in the editor (Undo brings the edits back)</source>
        <translation>Put the applied model's text back in the editor (Undo brings the edits back)</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window.cpp" line="-58" />
        <source>The scene's solids cannot be taken into the model's contacts (a shape that cannot serve): the model runs without touching them</source>
        <translation>The scene's solids cannot be taken into the model's contacts (a shape that cannot serve): the model runs without touching them</translation>
    </message>
    <message numerus="yes">
        <location line="+15" />
        <source>Model applied: %n bodies</source>
        <translation>
            <numerusform>Model applied: %n body</numerusform>
            <numerusform>Model applied: %n bodies</numerusform>
        </translation>
    </message>
    <message>
        <location line="+40" />
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+6" />
        <source>paused</source>
        <translation>paused</translation>
    </message>
    <message>
        <location line="+5" />
        <source>frame %1 ms</source>
        <translation>frame %1 ms</translation>
    </message>
    <message>
        <location line="+52" />
        <source>Simulation Stopped</source>
        <translation>Simulation Stopped</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1

The simulation is paused at the last good state; the editor stays usable. Reset to start again.</source>
        <translation>%1

The simulation is paused at the last good state; the editor stays usable. Reset to start again.</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_menus.cpp" line="+12" />
        <source>Model Language Reference</source>
        <translation>Model Language Reference</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The reference (docs/model-language.md) was not found at %1.</source>
        <translation>The reference (docs/model-language.md) was not found at %1.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>About Padrob Studio</source>
        <translation>About Padrob Studio</translation>
    </message>
    <message>
        <location line="+1" />
        <source>&lt;h3&gt;Padrob Studio %1&lt;/h3&gt;&lt;p&gt;Real-time training simulators of heavy machines, built from a model file: bodies, joints, hydraulic drives, forces and graphics.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Padrob Studio %1&lt;/h3&gt;&lt;p&gt;Real-time training simulators of heavy machines, built from a model file: bodies, joints, hydraulic drives, forces and graphics.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../ide/studio/app/main_window_tools.cpp" line="+37" />
        <location line="+137" />
        <source>Record Video</source>
        <translation>Record Video</translation>
    </message>
    <message>
        <location line="-76" />
        <source>Video saved: %1 (%2 s)</source>
        <translation>Video saved: %1 (%2 s)</translation>
    </message>
    <message>
        <location line="+15" />
        <source>%1 (%2)</source>
        <comment>an action and its shortcut</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Speed:</source>
        <translation>Speed:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Simulated seconds per second of the wall clock (Simulation ▸ Speed)</source>
        <translation>Simulated seconds per second of the wall clock (Simulation ▸ Speed)</translation>
    </message>
    <message>
        <location line="+58" />
        <source>Videos (*.mp4 *.mkv *.mov)</source>
        <translation>Videos (*.mp4 *.mkv *.mov)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Stop &amp;Recording</source>
        <translation>Stop &amp;Recording</translation>
    </message>
    <message>
        <location line="+0" />
        <source>&amp;Record Video…</source>
        <translation>&amp;Record Video…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stop recording the 3D view</source>
        <translation>Stop recording the 3D view</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Record a video of the 3D view (ffmpeg)</source>
        <translation>Record a video of the 3D view (ffmpeg)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>● REC %1:%2</source>
        <translation>● REC %1:%2</translation>
    </message>
</context>
<context>
    <name>studio::MappingTable</name>
    <message>
        <location filename="../ide/studio/station/mapping_table.cpp" line="+52" />
        <source>none</source>
        <translation>none</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The button's number on that device (as the channel lamps show it)</source>
        <translation>The button's number on that device (as the channel lamps show it)</translation>
    </message>
    <message>
        <location line="+104" />
        <location line="+15" />
        <source>Bank</source>
        <translation>Bank</translation>
    </message>
    <message>
        <location line="-15" />
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Axis</source>
        <translation>Axis</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Drive</source>
        <translation>Drive</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Gain</source>
        <translation>Gain</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Sign</source>
        <translation>Sign</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <location line="+2" />
        <source>A device id, or a kind (gamepad, joystick, serial, comedi, keyboard): the first connected device of that kind</source>
        <translation>A device id, or a kind (gamepad, joystick, serial, comedi, keyboard): the first connected device of that kind</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Command = gain × sign × calibrated value (0 … 10)</source>
        <translation>Command = gain × sign × calibrated value (0 … 10)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>What the mapping gives its drive now; after a profile change, a bank switch or a reconnection it waits until the lever is back at the centre</source>
        <translation>What the mapping gives its drive now; after a profile change, a bank switch or a reconnection it waits until the lever is back at the centre</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Add mapping</source>
        <translation>Add mapping</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A new row in the selected row's bank</source>
        <translation>A new row in the selected row's bank</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove mapping</source>
        <translation>Remove mapping</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Banks</source>
        <translation>Banks</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A device with fewer axes than the machine has drives switches between banks of mappings with its buttons; the “Always” mappings act in every bank.</source>
        <translation>A device with fewer axes than the machine has drives switches between banks of mappings with its buttons; the “Always” mappings act in every bank.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Selected by device</source>
        <translation>Selected by device</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Button</source>
        <translation>Button</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add bank</source>
        <translation>Add bank</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Rename bank</source>
        <translation>Rename bank</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove bank</source>
        <translation>Remove bank</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next bank:</source>
        <translation>Next bank:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The device whose button steps to the next bank</source>
        <translation>The device whose button steps to the next bank</translation>
    </message>
    <message>
        <location line="+93" />
        <source>Always</source>
        <translation>Always</translation>
    </message>
    <message>
        <location line="+2" />
        <location line="+425" />
        <source>Bank %1</source>
        <translation>Bank %1</translation>
    </message>
    <message>
        <location line="-415" />
        <source>The first connected device of this kind</source>
        <translation>The first connected device of this kind</translation>
    </message>
    <message>
        <location line="+19" />
        <location line="+8" />
        <source>Axis %1</source>
        <translation>Axis %1</translation>
    </message>
    <message>
        <location line="+27" />
        <source>C %1 (not in this model)</source>
        <translation>C %1 (not in this model)</translation>
    </message>
    <message>
        <location line="+35" />
        <source>−: the lever drives the valve the other way</source>
        <translation>−: the lever drives the valve the other way</translation>
    </message>
    <message numerus="yes">
        <location line="+83" />
        <source>%n more button(s) of the profile also select this bank</source>
        <translation>
            <numerusform>%n more button of the profile also selects this bank</numerusform>
            <numerusform>%n more buttons of the profile also select this bank</numerusform>
        </translation>
    </message>
    <message>
        <location line="+166" />
        <source>ignored</source>
        <translation>ignored</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The model has no such drive, or the gain or sign is not valid</source>
        <translation>The model has no such drive, or the gain or sign is not valid</translation>
    </message>
    <message>
        <location line="+3" />
        <source>no %1 found</source>
        <translation>no %1 found</translation>
    </message>
    <message>
        <location line="+3" />
        <source>device not connected</source>
        <translation>device not connected</translation>
    </message>
    <message>
        <location line="+3" />
        <source>bank not active</source>
        <translation>bank not active</translation>
    </message>
    <message>
        <location line="+3" />
        <source>waiting for centre</source>
        <translation>waiting for centre</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bring the lever back to the centre to take over this drive</source>
        <translation>Bring the lever back to the centre to take over this drive</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Contribution to the drive's command now (device %1)</source>
        <translation>Contribution to the drive's command now (device %1)</translation>
    </message>
    <message numerus="yes">
        <location line="+79" />
        <source>Remove the bank “%1” and its %n mapping(s)?</source>
        <translation>
            <numerusform>Remove the bank “%1” and its %n mapping?</numerusform>
            <numerusform>Remove the bank “%1” and its %n mappings?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::ModelDocument</name>
    <message>
        <location filename="../ide/studio/editor/model_document.cpp" line="+111" />
        <location line="+306" />
        <source>Untitled</source>
        <translation>Untitled</translation>
    </message>
    <message>
        <location line="-291" />
        <source>The file “%1” does not exist.</source>
        <translation>The file “%1” does not exist.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is a folder, not a model file.</source>
        <translation>“%1” is a folder, not a model file.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is not a regular file.</source>
        <translation>“%1” is not a regular file.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>“%1” is too large for a model file (%2 MB; at most %3 MB).</source>
        <translation>“%1” is too large for a model file (%2 MB; at most %3 MB).</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+2" />
        <source>Cannot read “%1”: %2.</source>
        <translation>Cannot read “%1”: %2.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>“%1” is not a text file (it contains binary data).</source>
        <translation>“%1” is not a text file (it contains binary data).</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Cannot save “%1”: it is a folder.</source>
        <translation>Cannot save “%1”: it is a folder.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the folder “%2” does not exist.</source>
        <translation>Cannot save “%1”: the folder “%2” does not exist.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the file is read-only.</source>
        <translation>Cannot save “%1”: the file is read-only.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Cannot save “%1”: the folder “%2” is not writable (permission denied). Save it somewhere else.</source>
        <translation>Cannot save “%1”: the folder “%2” is not writable (permission denied). Save it somewhere else.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Cannot save “%1”: %2.</source>
        <translation>Cannot save “%1”: %2.</translation>
    </message>
    <message>
        <location line="+41" />
        <source>The model has no file to reload.</source>
        <translation>The model has no file to reload.</translation>
    </message>
    <message>
        <location line="+20" />
        <source>The model has no file name yet: use Save As.</source>
        <translation>The model has no file name yet: use Save As.</translation>
    </message>
    <message>
        <location line="+109" />
        <source>cannot create the folder</source>
        <translation>cannot create the folder</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Cannot write the recovery copy “%1”: %2.</source>
        <translation>Cannot write the recovery copy “%1”: %2.</translation>
    </message>
    <message>
        <location line="+75" />
        <source>Cannot read the recovery copy “%1”: %2.</source>
        <translation>Cannot read the recovery copy “%1”: %2.</translation>
    </message>
</context>
<context>
    <name>studio::ModelTree</name>
    <message>
        <location filename="../ide/studio/tree/model_tree.cpp" line="+48" />
        <source>Element</source>
        <translation>Element</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Type</source>
        <translation>Type</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Role</source>
        <translation>Role</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Mass / limits</source>
        <translation>Mass / limits</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Drive</source>
        <translation>Drive</translation>
    </message>
    <message>
        <location line="+39" />
        <source>loop closure</source>
        <translation>loop closure</translation>
    </message>
    <message>
        <location line="+1" />
        <source>dependent</source>
        <translation>dependent</translation>
    </message>
    <message>
        <location line="+1" />
        <source>independent</source>
        <translation>independent</translation>
    </message>
    <message>
        <location line="+2" />
        <source>passive</source>
        <translation>passive</translation>
    </message>
    <message>
        <location line="+4" />
        <location line="+70" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="-70" />
        <source>C %1  %2</source>
        <translation>C %1  %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+29" />
        <location line="+1" />
        <source>ground</source>
        <translation>ground</translation>
    </message>
    <message>
        <location line="-29" />
        <source>B %1 %2</source>
        <translation>B %1 %2</translation>
    </message>
    <message>
        <location line="+0" />
        <location line="+37" />
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <location line="-34" />
        <source>Joint %1 (%2), line %3</source>
        <translation>Joint %1 (%2), line %3</translation>
    </message>
    <message>
        <location line="+1" />
        <source>between %1 and %2</source>
        <translation>between %1 and %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>limits: %1</source>
        <translation>limits: %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>drive: %1</source>
        <translation>drive: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>initial coordinate: %1</source>
        <translation>initial coordinate: %1</translation>
    </message>
    <message>
        <location line="+36" />
        <source>Body %1, line %2</source>
        <translation>Body %1, line %2</translation>
    </message>
    <message>
        <location line="+0" />
        <source>mass: %1</source>
        <translation>mass: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Ixx Iyy Izz: %1 %2 %3 kg·m²</source>
        <translation>Ixx Iyy Izz: %1 %2 %3 kg·m²</translation>
    </message>
    <message>
        <location line="+4" />
        <source>moved by joint C %1</source>
        <translation>moved by joint C %1</translation>
    </message>
    <message>
        <location line="-24" />
        <source>Bodies (%1)</source>
        <translation>Bodies (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>B 0  %1</source>
        <translation>B 0  %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>fixed</source>
        <translation>fixed</translation>
    </message>
    <message>
        <location line="+8" />
        <source>B %1  %2</source>
        <translation>B %1  %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>body</source>
        <translation>body</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Joints (%1)</source>
        <translation>Joints (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Chains (%1)</source>
        <translation>Chains (%1)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Chain %1:  %2</source>
        <translation>Chain %1:  %2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Loop closures (%1)</source>
        <translation>Loop closures (%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>none: the joints form an open tree</source>
        <translation>none: the joints form an open tree</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Coordinates (degrees of freedom: %1)</source>
        <translation>Coordinates (degrees of freedom: %1)</translation>
    </message>
    <message>
        <location line="+9" />
        <source>initially %1</source>
        <translation>initially %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Independent (%1)</source>
        <translation>Independent (%1)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Dependent (%1)</source>
        <translation>Dependent (%1)</translation>
    </message>
</context>
<context>
    <name>studio::OverrunMeter</name>
    <message>
        <location filename="../ide/studio/sim/overrun_meter.cpp" line="+29" />
        <source>%1 % of steps late</source>
        <translation>%1 % of steps late</translation>
    </message>
    <message numerus="yes">
        <location line="+5" />
        <source>An overrun is a solver step that took longer to compute than the real time it simulates: the simulation falls behind the wall clock. The share shown is that of the last %1 s (%n overrun(s) since Run).
A few are harmless. If the share stays high, this computer cannot keep up: lower the speed (Simulation ▸ Speed), close other programs, choose Settings ▸ Lighting ▸ At the vertices, or simplify the model.</source>
        <translation><numerusform>An overrun is a solver step that took longer to compute than the real time it simulates: the simulation falls behind the wall clock. The share shown is that of the last %1 s (%n overrun since Run).
A few are harmless. If the share stays high, this computer cannot keep up: lower the speed (Simulation ▸ Speed), close other programs, choose Settings ▸ Lighting ▸ At the vertices, or simplify the model.</numerusform><numerusform>An overrun is a solver step that took longer to compute than the real time it simulates: the simulation falls behind the wall clock. The share shown is that of the last %1 s (%n overruns since Run).
A few are harmless. If the share stays high, this computer cannot keep up: lower the speed (Simulation ▸ Speed), close other programs, choose Settings ▸ Lighting ▸ At the vertices, or simplify the model.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::PinDialog</name>
    <message>
        <location filename="../ide/studio/train/pin_dialog.cpp" line="+37" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+33" />
        <source>That is not the trainer's PIN. Try again.</source>
        <translation>That is not the trainer's PIN. Try again.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Type the trainer's PIN.</source>
        <translation>Type the trainer's PIN.</translation>
    </message>
    <message numerus="yes">
        <location line="+8" />
        <source>Too many wrong PINs: wait %n s.</source>
        <translation><numerusform>Too many wrong PINs: wait %n s.</numerusform><numerusform>Too many wrong PINs: wait %n s.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::PlotPanel</name>
    <message>
        <location filename="../ide/studio/plots/plot_panel.cpp" line="+150" />
        <source>Clear</source>
        <translation>Clear</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Forget the samples plotted so far</source>
        <translation>Forget the samples plotted so far</translation>
    </message>
    <message>
        <location line="+1" />
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export time and the ticked signals as CSV</source>
        <translation>Export time and the ticked signals as CSV</translation>
    </message>
    <message>
        <location line="+1" />
        <source>PNG…</source>
        <translation>PNG…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save the charts as a PNG image</source>
        <translation>Save the charts as a PNG image</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Tick signals in the list to plot them against time.</source>
        <translation>Tick signals in the list to plot them against time.</translation>
    </message>
    <message>
        <location line="+16" />
        <source>C %1</source>
        <translation>C %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>C %1 %2</source>
        <translation>C %1 %2</translation>
    </message>
    <message>
        <location line="-8" />
        <source>F drive</source>
        <translation>F drive</translation>
    </message>
    <message>
        <location line="-16" />
        <source>Tick the signals to plot; each unit gets its own chart, or choose beside a ticked signal a numbered chart to overlay signals of any units.</source>
        <translation>Tick the signals to plot; each unit gets its own chart, or choose beside a ticked signal a numbered chart to overlay signals of any units.</translation>
    </message>
    <message>
        <location line="+13" />
        <source>mechanical energy [J]</source>
        <translation>mechanical energy [J]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>largest contact force [kN]</source>
        <translation>largest contact force [kN]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 %2 [%3]</source>
        <comment>a signal: the joint, the quantity's symbol, its unit</comment>
        <translation>%1 %2 [%3]</translation>
    </message>
    <message>
        <location line="+6" />
        <source>pump %1</source>
        <translation>pump %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>pump %1 %2</source>
        <translation>pump %1 %2</translation>
    </message>
    <message>
        <location line="+284" />
        <source>The chart this signal is drawn in: its unit's, or a numbered one shared by signals of any units</source>
        <translation>The chart this signal is drawn in: its unit's, or a numbered one shared by signals of any units</translation>
    </message>
    <message>
        <location line="+2" />
        <source>by unit</source>
        <translation>by unit</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chart %1</source>
        <translation>chart %1</translation>
    </message>
    <message>
        <location line="+44" />
        <source>Mechanical energy [J]</source>
        <translation>Mechanical energy [J]</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Largest contact force [kN]</source>
        <translation>Largest contact force [kN]</translation>
    </message>
    <message>
        <location line="+12" />
        <source>coordinate q [%1]</source>
        <translation>coordinate q [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>translation along %1 q_%2 [%3]</source>
        <translation>translation along %1 q_%2 [%3]</translation>
    </message>
    <message>
        <location line="+4" />
        <source>rate dq/dt [%1]</source>
        <translation>rate dq/dt [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>velocity along %1 dq_%2/dt [%3]</source>
        <translation>velocity along %1 dq_%2/dt [%3]</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive force [%1]</source>
        <translation>drive force [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chamber A pressure p_A [%1]</source>
        <translation>chamber A pressure p_A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>chamber B pressure p_B [%1]</source>
        <translation>chamber B pressure p_B [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>supply pressure p_S [%1]</source>
        <translation>supply pressure p_S [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>delivered flow Q [%1]</source>
        <translation>delivered flow Q [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about A [%1]</source>
        <translation>reaction moment about A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about R [%1]</source>
        <translation>reaction moment about R [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction moment about T [%1]</source>
        <translation>reaction moment about T [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along A [%1]</source>
        <translation>reaction force along A [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along R [%1]</source>
        <translation>reaction force along R [%1]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>reaction force along T [%1]</source>
        <translation>reaction force along T [%1]</translation>
    </message>
    <message>
        <location line="+31" />
        <location line="+128" />
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location line="+31" />
        <source>Cannot save the image %1</source>
        <translation>Cannot save the image %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Export plots as CSV</source>
        <translation>Export plots as CSV</translation>
    </message>
    <message>
        <location line="+0" />
        <source>CSV files (*.csv)</source>
        <translation>CSV files (*.csv)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Save plots as PNG</source>
        <translation>Save plots as PNG</translation>
    </message>
    <message>
        <location line="+0" />
        <source>PNG images (*.png)</source>
        <translation>PNG images (*.png)</translation>
    </message>
</context>
<context>
    <name>studio::ProblemsView</name>
    <message>
        <location filename="../ide/studio/editor/problems_view.cpp" line="+45" />
        <source>Line:col</source>
        <translation>Line:col</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Message</source>
        <translation>Message</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Hint</source>
        <translation>Hint</translation>
    </message>
    <message>
        <location line="+37" />
        <source>%1 at %2: %3</source>
        <translation>%1 at %2: %3</translation>
    </message>
</context>
<context>
    <name>studio::ProfileDocument</name>
    <message>
        <location filename="../ide/studio/station/profile_document.cpp" line="+75" />
        <source>Cannot open the profile “%1”: %2</source>
        <translation>Cannot open the profile “%1”: %2</translation>
    </message>
    <message>
        <location line="+62" />
        <source>Cannot import %1: %2</source>
        <translation>Cannot import %1: %2</translation>
    </message>
</context>
<context>
    <name>studio::RecordsView</name>
    <message>
        <location filename="../ide/studio/train/records_view.cpp" line="+58" />
        <source>running</source>
        <translation>running</translation>
    </message>
    <message>
        <location line="+1" />
        <source>finished</source>
        <translation>finished</translation>
    </message>
    <message>
        <location line="+1" />
        <source>stopped</source>
        <translation>stopped</translation>
    </message>
    <message>
        <location line="+1" />
        <source>interrupted</source>
        <translation>interrupted</translation>
    </message>
    <message>
        <location line="+124" />
        <source>Trainee records</source>
        <translation>Trainee records</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operators</source>
        <translation>Operators</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Attempts</source>
        <translation>Attempts</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Passed</source>
        <translation>Passed</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Last attempt</source>
        <translation>Last attempt</translation>
    </message>
    <message>
        <location line="+1" />
        <source>code</source>
        <translation>code</translation>
    </message>
    <message>
        <location line="+1" />
        <source>name</source>
        <translation>name</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+46" />
        <source>Add operator</source>
        <translation>Add operator</translation>
    </message>
    <message>
        <location line="-45" />
        <source>Attempts (newest first)</source>
        <translation>Attempts (newest first)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Started</source>
        <translation>Started</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Tutorial</source>
        <translation>Tutorial</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Score</source>
        <translation>Score</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Time [s]</source>
        <translation>Time [s]</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Breakdown</source>
        <translation>Breakdown</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Measure</source>
        <translation>Measure</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Value</source>
        <translation>Value</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Of</source>
        <translation>Of</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Events</source>
        <translation>Events</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the course</source>
        <translation>Back to the course</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Refresh</source>
        <translation>Refresh</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export CSV…</source>
        <translation>Export CSV…</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Trainees see the expert in Trainer Mode</source>
        <translation>Trainees see the expert in Trainer Mode</translation>
    </message>
    <message>
        <location line="+1" />
        <source>In Trainer Mode the trainee cannot change this: the expert's translucent machine runs beside each attempt only when it is on.</source>
        <translation>In Trainer Mode the trainee cannot change this: the expert's translucent machine runs beside each attempt only when it is on.</translation>
    </message>
    <message>
        <location line="+31" />
        <location line="+4" />
        <source>Export CSV</source>
        <translation>Export CSV</translation>
    </message>
    <message>
        <location line="-3" />
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV files (*.csv);;All files (*)</translation>
    </message>
    <message>
        <location line="+79" />
        <location line="+168" />
        <location line="+17" />
        <source>There are no trainee records.</source>
        <translation>There are no trainee records.</translation>
    </message>
    <message>
        <location line="-182" />
        <source>The trainee records cannot be read: %1 Training goes on; attempts are kept in pending files and added to the records the next time they open.</source>
        <translation>The trainee records cannot be read: %1 Training goes on; attempts are kept in pending files and added to the records the next time they open.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The trainee records are open read-only: %1</source>
        <translation>The trainee records are open read-only: %1</translation>
    </message>
    <message>
        <location line="+16" />
        <source>Guest</source>
        <translation>Guest</translation>
    </message>
    <message>
        <location line="+31" />
        <source>passed</source>
        <translation>passed</translation>
    </message>
    <message>
        <location line="+0" />
        <source>not passed</source>
        <translation>not passed</translation>
    </message>
    <message>
        <location line="+35" />
        <source>%1 s — %2</source>
        <translation>%1 s — %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>(−%1)</source>
        <translation>(−%1)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>No events.</source>
        <translation>No events.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Score of each attempt</source>
        <translation>Score of each attempt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>attempt</source>
        <translation>attempt</translation>
    </message>
    <message>
        <location line="+3" />
        <source>score</source>
        <translation>score</translation>
    </message>
    <message>
        <location line="+37" />
        <source>pass mark %1 (%2)</source>
        <translation>pass mark %1 (%2)</translation>
    </message>
    <message>
        <location line="+28" />
        <source>Type the operator's code (badge number…).</source>
        <translation>Type the operator's code (badge number…).</translation>
    </message>
    <message numerus="yes">
        <location line="+18" />
        <source>Wrote %n attempt(s) to %1.</source>
        <translation><numerusform>Wrote %n attempt to %1.</numerusform><numerusform>Wrote %n attempts to %1.</numerusform></translation>
    </message>
</context>
<context>
    <name>studio::ResultScreen</name>
    <message>
        <location filename="../ide/studio/train/result_screen.cpp" line="+82" />
        <source>Measure</source>
        <translation>Measure</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Measured</source>
        <translation>Measured</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Points</source>
        <translation>Points</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Of</source>
        <translation>Of</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score</source>
        <translation>Score</translation>
    </message>
    <message>
        <location line="+1" />
        <source>What to improve</source>
        <translation>What to improve</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Course</source>
        <translation>Course</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Retry</source>
        <translation>Retry</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Debrief</source>
        <translation>Debrief</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Next stage</source>
        <translation>Next stage</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save as demonstration…</source>
        <translation>Save as demonstration…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Saves the operator's input of this attempt as an input log.</source>
        <translation>Saves the operator's input of this attempt as an input log.</translation>
    </message>
    <message>
        <location line="+1" />
        <location line="+27" />
        <source>Use as this stage's demonstration</source>
        <translation>Use as this stage's demonstration</translation>
    </message>
    <message>
        <location line="-26" />
        <source>From now on the demonstration, the expert and the comparison of this stage replay this attempt's input instead of the shipped one.</source>
        <translation>From now on the demonstration, the expert and the comparison of this stage replay this attempt's input instead of the shipped one.</translation>
    </message>
    <message>
        <location line="+12" />
        <location line="+6" />
        <source>Save as demonstration</source>
        <translation>Save as demonstration</translation>
    </message>
    <message>
        <location line="-3" />
        <source>Padrob input logs (*.log);;All files (*)</source>
        <translation>Padrob input logs (*.log);;All files (*)</translation>
    </message>
    <message>
        <location line="+38" />
        <source>PASSED</source>
        <translation>PASSED</translation>
    </message>
    <message>
        <location line="+0" />
        <source>NOT PASSED</source>
        <translation>NOT PASSED</translation>
    </message>
    <message>
        <location line="+5" />
        <source>The time ran out.</source>
        <translation>The time ran out.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine hit the scene too hard.</source>
        <translation>The machine hit the scene too hard.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The machine touched a worker.</source>
        <translation>The machine touched a worker.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The attempt was stopped.</source>
        <translation>The attempt was stopped.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The input ended before the goals were done.</source>
        <translation>The input ended before the goals were done.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The simulation failed.</source>
        <translation>The simulation failed.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Score %1 of 100 in %2 s</source>
        <translation>Score %1 of 100 in %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Work done: %1 % of the stage</source>
        <translation>Work done: %1 % of the stage</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The trainee records could not be written (%1); the attempt is kept and will be added the next time they can.</source>
        <translation>The trainee records could not be written (%1); the attempt is kept and will be added the next time they can.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This attempt is now the stage's demonstration.</source>
        <translation>This attempt is now the stage's demonstration.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 m/s³</source>
        <translation>%1 m/s³</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 penalty points</source>
        <translation>%1 penalty points</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Nothing: a clean run.</source>
        <translation>Nothing: a clean run.</translation>
    </message>
</context>
<context>
    <name>studio::SceneFile</name>
    <message>
        <location filename="../ide/studio/view/scene_file.cpp" line="+28" />
        <source>no such file</source>
        <translation>no such file</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cannot read the scene %1: %2</source>
        <translation>Cannot read the scene %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The scene %1 is too large (over %2 MB).</source>
        <translation>The scene %1 is too large (over %2 MB).</translation>
    </message>
    <message>
        <location line="+17" />
        <source>The scene %1 has errors:
%2</source>
        <translation>The scene %1 has errors:
%2</translation>
    </message>
    <message>
        <location line="+7" />
        <source>The scene %1 has no ground graphics (G … B 0) to draw.</source>
        <translation>The scene %1 has no ground graphics (G … B 0) to draw.</translation>
    </message>
    <message numerus="yes">
        <location line="+7" />
        <source>%n graphic(s) on moving bodies of the scene are not drawn.</source>
        <translation>
            <numerusform>%n graphic on a moving body of the scene is not drawn.</numerusform>
            <numerusform>%n graphics on moving bodies of the scene are not drawn.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>studio::SerialConsoleDialog</name>
    <message>
        <location filename="../ide/studio/station/serial_console_dialog.cpp" line="+54" />
        <source>Add serial console</source>
        <translation>Add serial console</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A replica console (levers on a DAQ box) on a serial port. The station opens it while this profile is in use, and tries again when it is unplugged.</source>
        <translation>A replica console (levers on a DAQ box) on a serial port. The station opens it while this profile is in use, and tries again when it is unplugged.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>serial number %1</source>
        <translation>serial number %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>e.g. /dev/ttyACM0</source>
        <translation>e.g. /dev/ttyACM0</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The port's name exactly as the profile will keep it (a /dev/serial/by-id/… link stays the same when the box is plugged elsewhere)</source>
        <translation>The port's name exactly as the profile will keep it (a /dev/serial/by-id/… link stays the same when the box is plugged elsewhere)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Baud rate:</source>
        <translation>Baud rate:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add</source>
        <translation>Add</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
    <message>
        <location line="+13" />
        <source>No serial port found now; type the port's name.</source>
        <translation>No serial port found now; type the port's name.</translation>
    </message>
</context>
<context>
    <name>studio::SimulationRunner</name>
    <message>
        <location filename="../ide/studio/sim/simulation_runner.cpp" line="+459" />
        <source>The simulation stopped: %1</source>
        <translation>The simulation stopped: %1</translation>
    </message>
    <message>
        <location line="+65" />
        <source>The simulation cannot start: %1</source>
        <translation>The simulation cannot start: %1</translation>
    </message>
</context>
<context>
    <name>studio::StartScreen</name>
    <message>
        <location filename="../ide/studio/train/start_screen.cpp" line="+56" />
        <source>Watch the demonstration</source>
        <translation>Watch the demonstration</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Back to the course</source>
        <translation>Back to the course</translation>
    </message>
    <message>
        <location line="+26" />
        <location line="+47" />
        <location line="+73" />
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="-120" />
        <location line="+47" />
        <location line="+106" />
        <location line="+20" />
        <source>Play</source>
        <translation>Play</translation>
    </message>
    <message>
        <location line="-142" />
        <source>Speed:</source>
        <translation>Speed:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Expert's camera</source>
        <translation>Expert's camera</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Look where the expert looked while recording (untick to move the view yourself).</source>
        <translation>Look where the expert looked while recording (untick to move the view yourself).</translation>
    </message>
    <message>
        <location line="+59" />
        <source>Time limit: %1 s. Pass mark: %2 of 100.</source>
        <translation>Time limit: %1 s. Pass mark: %2 of 100.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>How to drive (%1):</source>
        <translation>How to drive (%1):</translation>
    </message>
    <message>
        <location line="+5" />
        <source>This tutorial has no demonstration.</source>
        <translation>This tutorial has no demonstration.</translation>
    </message>
    <message>
        <location line="+43" />
        <source>%1 s of %2 s</source>
        <translation>%1 s of %2 s</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Done: passed, %1 of 100</source>
        <translation>Done: passed, %1 of 100</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Done</source>
        <translation>Done</translation>
    </message>
</context>
<context>
    <name>studio::StationHud</name>
    <message>
        <location filename="../ide/studio/station/live_state.cpp" line="+26" />
        <source>Bank: &lt;b&gt;%1&lt;/b&gt; (%2 of %3)</source>
        <translation>Bank: &lt;b&gt;%1&lt;/b&gt; (%2 of %3)</translation>
    </message>
</context>
<context>
    <name>studio::StationPage</name>
    <message>
        <location line="+44" />
        <source>Connected</source>
        <translation>Connected</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Disconnected</source>
        <translation>Disconnected</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Stalled</source>
        <translation>Stalled</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Failed</source>
        <translation>Failed</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page.cpp" line="+62" />
        <source>The bank of mappings the operator's levers drive now</source>
        <translation>The bank of mappings the operator's levers drive now</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Valve mapping</source>
        <translation>Valve mapping</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Remove bank</source>
        <translation>Remove bank</translation>
    </message>
    <message>
        <location line="+51" />
        <source>Profile:</source>
        <translation>Profile:</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The station profiles of this model: yours, and those shipped with it</source>
        <translation>The station profiles of this model: yours, and those shipped with it</translation>
    </message>
    <message>
        <location line="+1" />
        <source>New</source>
        <translation>New</translation>
    </message>
    <message>
        <location line="+1" />
        <source>An empty profile with one bank</source>
        <translation>An empty profile with one bank</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save</source>
        <translation>Save</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save the profile under its name (a shipped profile is saved as your own copy)</source>
        <translation>Save the profile under its name (a shipped profile is saved as your own copy)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save As…</source>
        <translation>Save As…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete</source>
        <translation>Delete</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Delete this profile of yours (shipped profiles cannot be deleted)</source>
        <translation>Delete this profile of yours (shipped profiles cannot be deleted)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Import…</source>
        <translation>Import…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Add a profile file (from another station) to this model's profiles</source>
        <translation>Add a profile file (from another station) to this model's profiles</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Export…</source>
        <translation>Export…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Write this profile to a file</source>
        <translation>Write this profile to a file</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Problems of this profile with this model: a mapping with a warning is ignored</source>
        <translation>Problems of this profile with this model: a mapping with a warning is ignored</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Devices</source>
        <translation>Devices</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Device</source>
        <translation>Device</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Samples</source>
        <translation>Samples</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Dropped</source>
        <translation>Dropped</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Readings dropped as corrupt (a serial line with a bad checksum…)</source>
        <translation>Readings dropped as corrupt (a serial line with a bad checksum…)</translation>
    </message>
    <message>
        <location line="+33" />
        <source>Add serial console…</source>
        <translation>Add serial console…</translation>
    </message>
    <message>
        <location line="+1" />
        <source>A replica console (DAQ box) on a serial port, kept in the profile</source>
        <translation>A replica console (DAQ box) on a serial port, kept in the profile</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove</source>
        <translation>Remove</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Remove the selected device from the profile (only devices the profile opens: joysticks and gamepads are found by themselves)</source>
        <translation>Remove the selected device from the profile (only devices the profile opens: joysticks and gamepads are found by themselves)</translation>
    </message>
    <message>
        <location line="-6" />
        <location line="+464" />
        <source>Record input…</source>
        <translation>Record input…</translation>
    </message>
    <message>
        <location line="-456" />
        <source>Write everything the devices read to an input log</source>
        <translation>Write everything the devices read to an input log</translation>
    </message>
    <message>
        <location line="-7" />
        <location line="+465" />
        <source>Replay a log…</source>
        <translation>Replay a log…</translation>
    </message>
    <message>
        <location line="-457" />
        <source>Play a recorded input log: it drives the machine instead of the operator</source>
        <translation>Play a recorded input log: it drives the machine instead of the operator</translation>
    </message>
    <message>
        <location line="+26" />
        <source>Channels</source>
        <translation>Channels</translation>
    </message>
    <message>
        <location line="+51" />
        <source>(no name)</source>
        <translation>(no name)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (not saved)</source>
        <translation>%1 (not saved)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>This profile is not saved yet</source>
        <translation>This profile is not saved yet</translation>
    </message>
    <message>
        <location line="+5" />
        <source>%1 (unreadable)</source>
        <translation>%1 (unreadable)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1 (shipped)</source>
        <translation>%1 (shipped)</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Unsaved changes</source>
        <translation>Unsaved changes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The profile “%1” has changes that are not saved. Discard them?</source>
        <translation>The profile “%1” has changes that are not saved. Discard them?</translation>
    </message>
    <message>
        <location line="+43" />
        <source>New profile</source>
        <translation>New profile</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name of the new profile:</source>
        <translation>Name of the new profile:</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bank 1</source>
        <translation>Bank 1</translation>
    </message>
    <message>
        <location line="+14" />
        <source>Save profile as</source>
        <translation>Save profile as</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Name of the profile:</source>
        <translation>Name of the profile:</translation>
    </message>
    <message>
        <location line="+9" />
        <source>A profile needs a name.</source>
        <translation>A profile needs a name.</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Replace profile</source>
        <translation>Replace profile</translation>
    </message>
    <message>
        <location line="+0" />
        <source>A profile named “%1” exists already for this model. Replace it?</source>
        <translation>A profile named “%1” exists already for this model. Replace it?</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Cannot save the profile: %1</source>
        <translation>Cannot save the profile: %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Save profile</source>
        <translation>Save profile</translation>
    </message>
    <message>
        <location line="+18" />
        <location line="+4" />
        <source>Delete profile</source>
        <translation>Delete profile</translation>
    </message>
    <message>
        <location line="-4" />
        <source>Delete the profile “%1”? This cannot be undone.</source>
        <translation>Delete the profile “%1”? This cannot be undone.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Cannot delete the profile: %1</source>
        <translation>Cannot delete the profile: %1</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Import station profile</source>
        <translation>Import station profile</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Station profiles (*.json);;All files (*)</source>
        <translation>Station profiles (*.json);;All files (*)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Import profile</source>
        <translation>Import profile</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Export station profile</source>
        <translation>Export station profile</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Station profiles (*.json)</source>
        <translation>Station profiles (*.json)</translation>
    </message>
    <message>
        <location line="+6" />
        <location line="+6" />
        <source>Export profile</source>
        <translation>Export profile</translation>
    </message>
    <message>
        <location line="-6" />
        <location filename="../ide/studio/station/station_page_devices.cpp" line="+82" />
        <source>%1 exists already. Replace it?</source>
        <translation>%1 exists already. Replace it?</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Cannot export the profile: %1</source>
        <translation>Cannot export the profile: %1</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page_devices.cpp" line="-55" />
        <source>Add serial console</source>
        <translation>Add serial console</translation>
    </message>
    <message>
        <location line="+0" />
        <source>“%1” is not a serial port (serial:/dev/…)</source>
        <translation>“%1” is not a serial port (serial:/dev/…)</translation>
    </message>
    <message>
        <location line="+51" />
        <location line="+4" />
        <location line="+4" />
        <location line="+17" />
        <source>Record input</source>
        <translation>Record input</translation>
    </message>
    <message>
        <location line="-25" />
        <location line="+33" />
        <source>Padrob input logs (*.log);;All files (*)</source>
        <translation>Padrob input logs (*.log);;All files (*)</translation>
    </message>
    <message>
        <location line="-25" />
        <source>Cannot record to %1: %2</source>
        <translation>Cannot record to %1: %2</translation>
    </message>
    <message>
        <location line="+17" />
        <source>The log %1 may be incomplete: %2</source>
        <translation>The log %1 may be incomplete: %2</translation>
    </message>
    <message>
        <location line="+8" />
        <location line="+5" />
        <location line="+4" />
        <source>Replay a log</source>
        <translation>Replay a log</translation>
    </message>
    <message>
        <location line="-4" />
        <source>Cannot replay %1: %2</source>
        <translation>Cannot replay %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 has no devices to replay</source>
        <translation>%1 has no devices to replay</translation>
    </message>
    <message>
        <location filename="../ide/studio/station/station_page.cpp" line="+30" />
        <source>● Recording to %1 (%2 s)</source>
        <translation>● Recording to %1 (%2 s)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>▶ Replaying %1</source>
        <translation>▶ Replaying %1</translation>
    </message>
    <message>
        <location line="+13" />
        <source>Error — %1</source>
        <translation>Error — %1</translation>
    </message>
    <message>
        <location line="+0" />
        <source>Warning — %1</source>
        <translation>Warning — %1</translation>
    </message>
    <message>
        <location line="+17" />
        <source>No banks</source>
        <translation>No banks</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bank %1</source>
        <translation>Bank %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bank: %1 (%2 of %3)</source>
        <translation>Bank: %1 (%2 of %3)</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Bank: %1</source>
        <translation>Bank: %1</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Replaying %1: the operator's devices are ignored</source>
        <translation>Replaying %1: the operator's devices are ignored</translation>
    </message>
    <message>
        <location line="+29" />
        <source>%1 (replay)</source>
        <translation>%1 (replay)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <location line="+1" />
        <source>%1
Kind: %2
Id: %3</source>
        <translation>%1
Kind: %2
Id: %3</translation>
    </message>
    <message>
        <location line="+19" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Stop recording</source>
        <translation>Stop recording</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Stop replay</source>
        <translation>Stop replay</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Yes</source>
        <translation>Yes</translation>
    </message>
    <message>
        <location line="+1" />
        <source>No</source>
        <translation>No</translation>
    </message>
    <message>
        <location line="+10" />
        <location line="+26" />
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="-25" />
        <source>Cancel</source>
        <translation>Cancel</translation>
    </message>
</context>
<context>
    <name>studio::TrainPage</name>
    <message>
        <location filename="../ide/studio/train/train_page.cpp" line="+149" />
        <source>Trainee records</source>
        <translation>Trainee records</translation>
    </message>
    <message>
        <location line="+0" />
        <source>The trainer's PIN:</source>
        <translation>The trainer's PIN:</translation>
    </message>
    <message>
        <location line="+218" />
        <source>On the centre's network as %1</source>
        <translation>On the centre's network as %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>On the centre's network as %1, but without the centre's key: the instructor's commands are refused (%2)</source>
        <translation>On the centre's network as %1, but without the centre's key: the instructor's commands are refused (%2)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Not on the centre's network: %1</source>
        <translation>Not on the centre's network: %1</translation>
    </message>
</context>
<context>
    <name>studio::TrainStation</name>
    <message>
        <location filename="../ide/studio/centre/train_station.cpp" line="+93" />
        <source>no key file was given (--centre-key)</source>
        <translation>no key file was given (--centre-key)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>DDS refused to join the domain</source>
        <translation>DDS refused to join the domain</translation>
    </message>
</context>
<context>
    <name>studio::TrainingController</name>
    <message>
        <location filename="../ide/studio/train/training_controller.cpp" line="+211" />
        <location line="+242" />
        <source>Guest</source>
        <translation>Guest</translation>
    </message>
    <message>
        <location line="-157" />
        <source>The demonstration chosen for this stage (%1) cannot be read: %2. The shipped demonstration is used.</source>
        <translation>The demonstration chosen for this stage (%1) cannot be read: %2. The shipped demonstration is used.</translation>
    </message>
    <message>
        <location line="+52" />
        <source>There is no recorded input: only an attempt with the operator's controls is recorded.</source>
        <translation>There is no recorded input: only an attempt with the operator's controls is recorded.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Cannot write %1.</source>
        <translation>Cannot write %1.</translation>
    </message>
</context>
<context>
    <name>studio::VideoRecorder</name>
    <message>
        <location filename="../ide/studio/view/video_recorder.cpp" line="+54" />
        <source>A video is being recorded already.</source>
        <translation>A video is being recorded already.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Recording a video needs the program ffmpeg, which was not found. Install it (on Debian and Ubuntu: sudo apt install ffmpeg) and try again.</source>
        <translation>Recording a video needs the program ffmpeg, which was not found. Install it (on Debian and Ubuntu: sudo apt install ffmpeg) and try again.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1 is not a regular file (a folder, a device or a pipe): it is not overwritten.</source>
        <translation>%1 is not a regular file (a folder, a device or a pipe): it is not overwritten.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 is a file Padrob Studio has open (the model or the scene): it is not overwritten.</source>
        <translation>%1 is a file Padrob Studio has open (the model or the scene): it is not overwritten.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The folder %1 cannot be written.</source>
        <translation>The folder %1 cannot be written.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The 3D view cannot be drawn (no OpenGL 3.3): there is nothing to record.</source>
        <translation>The 3D view cannot be drawn (no OpenGL 3.3): there is nothing to record.</translation>
    </message>
    <message>
        <location line="+24" />
        <source>ffmpeg (%1) could not be started: %2</source>
        <translation>ffmpeg (%1) could not be started: %2</translation>
    </message>
    <message>
        <location line="+58" />
        <source>ffmpeg stopped with an error while writing %1</source>
        <translation>ffmpeg stopped with an error while writing %1</translation>
    </message>
</context>
<context>
    <name>studio::Viewport</name>
    <message>
        <location filename="../ide/studio/view/scene_geometry.cpp" line="+164" />
        <source>no file named</source>
        <translation>no file named</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the file was not found (looked for %1)</source>
        <translation>the file was not found (looked for %1)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>the file holds no triangles</source>
        <translation>the file holds no triangles</translation>
    </message>
    <message>
        <location line="+1" />
        <source>it cannot be read: %1</source>
        <translation>it cannot be read: %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Graphic %1 (body %2): mesh "%3" is drawn as a box: %4.</source>
        <translation>Graphic %1 (body %2): mesh "%3" is drawn as a box: %4.</translation>
    </message>
    <message>
        <location filename="../ide/studio/view/viewport.cpp" line="+226" />
        <source>Iso</source>
        <translation>Iso</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Front</source>
        <translation>Front</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Side</source>
        <translation>Side</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Top</source>
        <translation>Top</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Operator seat</source>
        <translation>Operator seat</translation>
    </message>
    <message>
        <location line="+107" />
        <source>The 3D view needs OpenGL 3.3, which this system does not provide.</source>
        <translation>The 3D view needs OpenGL 3.3, which this system does not provide.</translation>
    </message>
    <message>
        <location line="+1" />
        <source>The 3D view's shaders do not build: %1</source>
        <translation>The 3D view's shaders do not build: %1</translation>
    </message>
</context>
<context>
    <name>studio::ViewportLayout</name>
    <message>
        <location filename="../ide/studio/view/viewport_layout.cpp" line="+45" />
        <source>The operator's screens are shown in separate windows.</source>
        <translation>The operator's screens are shown in separate windows.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Operator screen %1 of %2</source>
        <translation>Operator screen %1 of %2</translation>
    </message>
</context>
<context>
    <name>studio::main</name>
    <message>
        <location filename="../ide/studio/main.cpp" line="+85" />
        <source>Padrob Studio: write a machine's model, simulate it in real time and drive it from the operator's devices.</source>
        <translation>Padrob Studio: write a machine's model, simulate it in real time and drive it from the operator's devices.</translation>
    </message>
    <message>
        <location line="+12" />
        <source>The model file to open (default: the liner manipulator).</source>
        <translation>The model file to open (default: the liner manipulator).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Draw the ground graphics of FILE around the model (a scene such as resources/scenes/sag_mill.pad). Without it, the scene used last.</source>
        <translation>Draw the ground graphics of FILE around the model (a scene such as resources/scenes/sag_mill.pad). Without it, the scene used last.</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+41" />
        <location line="+25" />
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location line="-63" />
        <source>Measure instead of working, then quit: the start-up time, N frames of a 1920x1080 window paced at 60 Hz and N back to back, with one view and with three, the solver's step periods meanwhile, and the latency of 60 key presses to the solver.</source>
        <translation>Measure instead of working, then quit: the start-up time, N frames of a 1920x1080 window paced at 60 Hz and N back to back, with one view and with three, the solver's step periods meanwhile, and the latency of 60 key presses to the solver.</translation>
    </message>
    <message>
        <location line="+8" />
        <source>With --bench-frames: only one view (1) or only three (3).</source>
        <translation>With --bench-frames: only one view (1) or only three (3).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>With --bench-frames: print the results as one JSON object.</source>
        <translation>With --bench-frames: print the results as one JSON object.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Kiosk mode for the training room: only the Train workspace, full screen, without menus. Ctrl+Shift+F12 leaves it (asking the trainer's PIN when one is set).</source>
        <translation>Kiosk mode for the training room: only the Train workspace, full screen, without menus. Ctrl+Shift+F12 leaves it (asking the trainer's PIN when one is set).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>With --trainer: the operator in training.</source>
        <translation>With --trainer: the operator in training.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The language of the application and the tutorials (es or en).</source>
        <translation>The language of the application and the tutorials (es or en).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Where the 3D view computes its light: at every pixel (finer), at the vertices (faster on a software OpenGL), or auto: at the vertices on a software OpenGL, at every pixel on a GPU. Without it, the choice made in Settings &gt; Lighting (auto at first; --bench-frames: auto).</source>
        <translation>Where the 3D view computes its light: at every pixel (finer), at the vertices (faster on a software OpenGL), or auto: at the vertices on a software OpenGL, at every pixel on a GPU. Without it, the choice made in Settings &gt; Lighting (auto at first; --bench-frames: auto).</translation>
    </message>
    <message>
        <location line="+55" />
        <source>Make the Train workspace a station of the training centre named NAME (unique in the centre): it publishes its attempt and obeys the instructor's signed commands.</source>
        <translation>Make the Train workspace a station of the training centre named NAME (unique in the centre): it publishes its attempt and obeys the instructor's signed commands.</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+12" />
        <source>NAME</source>
        <translation>NAME</translation>
    </message>
    <message>
        <location line="-9" />
        <source>DDS Security: authenticated, access-controlled, encrypted traffic, with the centre's PKI in DIR and this node's identity in DIR/nodes/NAME (see 'padrob centre pki').</source>
        <translation>DDS Security: authenticated, access-controlled, encrypted traffic, with the centre's PKI in DIR and this node's identity in DIR/nodes/NAME (see 'padrob centre pki').</translation>
    </message>
    <message>
        <location line="+3" />
        <source>DIR</source>
        <translation>DIR</translation>
    </message>
    <message>
        <location line="+3" />
        <source>With --instructor or --display-of: this node's name in the centre (its identity in the PKI with --security). Default: instructor@HOST, display-STATION-VIEW.</source>
        <translation>With --instructor or --display-of: this node's name in the centre (its identity in the PKI with --security). Default: instructor@HOST, display-STATION-VIEW.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>--lang must be es or en.</source>
        <translation>--lang must be es or en.</translation>
    </message>
    <message>
        <location line="+11" />
        <source>--lighting must be auto, pixel or vertex.</source>
        <translation>--lighting must be auto, pixel or vertex.</translation>
    </message>
    <message>
        <location line="+18" />
        <source>--bench-frames needs a number of frames (1 or more) and --views 1 or 3.</source>
        <translation>--bench-frames needs a number of frames (1 or more) and --views 1 or 3.</translation>
    </message>
    <message>
        <location line="-98" />
        <source>Be a display node of the training centre: show STATION's machine from its operator's seat, driven by its state stream.</source>
        <translation>Be a display node of the training centre: show STATION's machine from its operator's seat, driven by its state stream.</translation>
    </message>
    <message>
        <location line="-60" />
        <source>Show this help and quit.</source>
        <translation>Show this help and quit.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Show the version and quit.</source>
        <translation>Show the version and quit.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>model</source>
        <translation>model</translation>
    </message>
    <message>
        <location line="+2" />
        <source>[MODEL]</source>
        <translation>[MODEL]</translation>
    </message>
    <message>
        <location line="+45" />
        <source>Start as usual, save the window to FILE (PNG) once the model is drawn, print the model's file, and quit.</source>
        <translation>Start as usual, save the window to FILE (PNG) once the model is drawn, print the model's file, and quit.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>STATION</source>
        <translation>STATION</translation>
    </message>
    <message>
        <location line="+3" />
        <source>With --display-of: which of the station's three screens (default centre).</source>
        <translation>With --display-of: which of the station's three screens (default centre).</translation>
    </message>
    <message>
        <location line="+5" />
        <source>Be the instructor's station of the training centre: watch the stations and command them.</source>
        <translation>Be the instructor's station of the training centre: watch the stations and command them.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>With --instructor, --display-of or --station-name: the centre's key, which signs everything a node of the centre says and checks everything it hears (without it the instructor and the display see nothing, and the station refuses every command and is heard by no one).</source>
        <translation>With --instructor, --display-of or --station-name: the centre's key, which signs everything a node of the centre says and checks everything it hears (without it the instructor and the display see nothing, and the station refuses every command and is heard by no one).</translation>
    </message>
    <message>
        <location line="+8" />
        <source>The training centre's DDS domain, 0-232 (default 0).</source>
        <translation>The training centre's DDS domain, 0-232 (default 0).</translation>
    </message>
    <message>
        <location line="+4" />
        <source>The training centre on this computer only.</source>
        <translation>The training centre on this computer only.</translation>
    </message>
    <message>
        <location line="+3" />
        <source>The network interface of the training centre (name or address; repeatable).</source>
        <translation>The network interface of the training centre (name or address; repeatable).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>INTERFACE</source>
        <translation>INTERFACE</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Find the centre's other computers by unicast at ADDRESS (repeatable; without it, multicast).</source>
        <translation>Find the centre's other computers by unicast at ADDRESS (repeatable; without it, multicast).</translation>
    </message>
    <message>
        <location line="+2" />
        <source>ADDRESS</source>
        <translation>ADDRESS</translation>
    </message>
    <message>
        <location line="+89" />
        <source>--domain must be a whole number from 0 to 232.</source>
        <translation>--domain must be a whole number from 0 to 232.</translation>
    </message>
    <message>
        <location line="+15" />
        <source>--station-name needs a name.</source>
        <translation>--station-name needs a name.</translation>
    </message>
    <message>
        <location line="+9" />
        <source>--view must be left, centre or right.</source>
        <translation>--view must be left, centre or right.</translation>
    </message>
</context>
<context>
    <name>trainer::ChannelCalibration</name>
    <message>
        <location filename="../trainer/station/calibration.cpp" line="+36" />
        <source>a value is not a number</source>
        <translation>a value is not a number</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the raw minimum must be below the raw maximum</source>
        <translation>the raw minimum must be below the raw maximum</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the centre must lie between the minimum and the maximum</source>
        <translation>the centre must lie between the minimum and the maximum</translation>
    </message>
    <message>
        <location line="+2" />
        <source>dead bands must be between 0 and 0.9 of the travel</source>
        <translation>dead bands must be between 0 and 0.9 of the travel</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the exponential curve's parameter must be between 0.05 and 10</source>
        <translation>the exponential curve's parameter must be between 0.05 and 10</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the filter's cutoff cannot be negative</source>
        <translation>the filter's cutoff cannot be negative</translation>
    </message>
    <message>
        <location line="+52" />
        <source>“%1” must be a number</source>
        <translation>“%1” must be a number</translation>
    </message>
    <message>
        <location line="+10" />
        <source>“%1” must be true or false</source>
        <translation>“%1” must be true or false</translation>
    </message>
    <message>
        <location line="+16" />
        <source>“curve” must be "linear" or "exponential"</source>
        <translation>“curve” must be "linear" or "exponential"</translation>
    </message>
    <message>
        <location line="+63" />
        <source>Leave the lever at rest to capture its centre.</source>
        <translation>Leave the lever at rest to capture its centre.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Move the lever to its full travel, both ways.</source>
        <translation>Move the lever to its full travel, both ways.</translation>
    </message>
</context>
<context>
    <name>trainer::ComediDaq</name>
    <message>
        <location filename="../trainer/input/comedi_daq.cpp" line="+11" />
        <source>Comedi card %1</source>
        <translation>Comedi card %1</translation>
    </message>
    <message>
        <location line="+23" />
        <source>Cannot open the Comedi card %1: %2. The card's kernel driver must be loaded and the device configured with comedi_config. Trying again every 2 s.</source>
        <translation>Cannot open the Comedi card %1: %2. The card's kernel driver must be loaded and the device configured with comedi_config. Trying again every 2 s.</translation>
    </message>
    <message>
        <location line="+10" />
        <source>The Comedi card %1 has no analog inputs. Trying again every 2 s.</source>
        <translation>The Comedi card %1 has no analog inputs. Trying again every 2 s.</translation>
    </message>
    <message>
        <location line="+14" />
        <source>AI %1</source>
        <translation>AI %1</translation>
    </message>
    <message>
        <location line="+37" />
        <source>Reading the Comedi card %1 failed (%2); trying again every 2 s.</source>
        <translation>Reading the Comedi card %1 failed (%2); trying again every 2 s.</translation>
    </message>
</context>
<context>
    <name>trainer::Gamepad</name>
    <message>
        <location filename="../trainer/station/control_names.cpp" line="+21" />
        <source>Left stick X</source>
        <translation>Left stick X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left stick Y</source>
        <translation>Left stick Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick X</source>
        <translation>Right stick X</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick Y</source>
        <translation>Right stick Y</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left trigger</source>
        <translation>Left trigger</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right trigger</source>
        <translation>Right trigger</translation>
    </message>
    <message>
        <location line="+12" />
        <source>Back</source>
        <translation>Back</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Guide</source>
        <translation>Guide</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left stick press</source>
        <translation>Left stick press</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right stick press</source>
        <translation>Right stick press</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Left shoulder</source>
        <translation>Left shoulder</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Right shoulder</source>
        <translation>Right shoulder</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad up</source>
        <translation>D-pad up</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad down</source>
        <translation>D-pad down</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad left</source>
        <translation>D-pad left</translation>
    </message>
    <message>
        <location line="+1" />
        <source>D-pad right</source>
        <translation>D-pad right</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Misc</source>
        <translation>Misc</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Paddle %1</source>
        <translation>Paddle %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Touchpad</source>
        <translation>Touchpad</translation>
    </message>
    <message>
        <location line="+8" />
        <source>LS</source>
        <comment>left stick pressed, on a small lamp</comment>
        <translation>LS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RS</source>
        <comment>right stick pressed, on a small lamp</comment>
        <translation>RS</translation>
    </message>
    <message>
        <location line="+1" />
        <source>LB</source>
        <comment>left shoulder button, on a small lamp</comment>
        <translation>LB</translation>
    </message>
    <message>
        <location line="+1" />
        <source>RB</source>
        <comment>right shoulder button, on a small lamp</comment>
        <translation>RB</translation>
    </message>
    <message>
        <location line="+25" />
        <source>Axis %1</source>
        <translation>Axis %1</translation>
    </message>
    <message>
        <location line="+10" />
        <source>Button %1</source>
        <translation>Button %1</translation>
    </message>
</context>
<context>
    <name>trainer::InputDevice</name>
    <message>
        <location filename="../trainer/input/input_device.cpp" line="+10" />
        <source>Joystick</source>
        <translation>Joystick</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Gamepad</source>
        <translation>Gamepad</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Serial DAQ console</source>
        <translation>Serial DAQ console</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Comedi DAQ card</source>
        <translation>Comedi DAQ card</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Keyboard</source>
        <translation>Keyboard</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Replay</source>
        <translation>Replay</translation>
    </message>
</context>
<context>
    <name>trainer::InputLog</name>
    <message>
        <location filename="../trainer/input/input_log.cpp" line="+13" />
        <source>line %1: %2</source>
        <translation>line %1: %2</translation>
    </message>
    <message>
        <location line="+4" />
        <source>not a Padrob input log (the first line must be “%1”)</source>
        <translation>not a Padrob input log (the first line must be “%1”)</translation>
    </message>
    <message>
        <location line="+11" />
        <source>devices must be numbered 0, 1, 2… in order</source>
        <translation>devices must be numbered 0, 1, 2… in order</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the device description is not valid JSON (%1)</source>
        <translation>the device description is not valid JSON (%1)</translation>
    </message>
    <message>
        <location line="+6" />
        <source>a device needs an “id” and a known “kind”</source>
        <translation>a device needs an “id” and a known “kind”</translation>
    </message>
    <message>
        <location line="+16" />
        <source>the time must be a number that never goes back</source>
        <translation>the time must be a number that never goes back</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the device number (the second field, after the time) is missing</source>
        <translation>the device number (the second field, after the time) is missing</translation>
    </message>
    <message>
        <location line="+3" />
        <source>device %1 is not described above this line</source>
        <translation>device %1 is not described above this line</translation>
    </message>
    <message>
        <location line="+4" />
        <source>%1 values where device %2 has %3 axes and %4 buttons</source>
        <translation>%1 values where device %2 has %3 axes and %4 buttons</translation>
    </message>
    <message>
        <location line="+7" />
        <source>axis %1 is not a number</source>
        <translation>axis %1 is not a number</translation>
    </message>
    <message>
        <location line="+5" />
        <source>button %1 must be 0 or 1</source>
        <translation>button %1 must be 0 or 1</translation>
    </message>
    <message>
        <location line="+20" />
        <location line="+43" />
        <source>cannot write %1: %2</source>
        <translation>cannot write %1: %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Replay of %1</source>
        <translation>Replay of %1</translation>
    </message>
</context>
<context>
    <name>trainer::KeyboardDevice</name>
    <message>
        <location filename="../trainer/input/input_device.cpp" line="+8" />
        <location filename="../trainer/input/keyboard_device.cpp" line="+12" />
        <source>Keyboard</source>
        <translation>Keyboard</translation>
    </message>
</context>
<context>
    <name>trainer::ProfileStore</name>
    <message>
        <location filename="../trainer/station/profile_store.cpp" line="+98" />
        <source>there is no profile “%1” for %2</source>
        <translation>there is no profile “%1” for %2</translation>
    </message>
    <message>
        <location line="+18" />
        <source>a profile needs a name</source>
        <translation>a profile needs a name</translation>
    </message>
    <message>
        <location line="+6" />
        <source>a profile named “%1” exists already</source>
        <translation>a profile named “%1” exists already</translation>
    </message>
    <message>
        <location line="+9" />
        <source>cannot keep the old %1 aside; nothing was saved</source>
        <translation>cannot keep the old %1 aside; nothing was saved</translation>
    </message>
    <message>
        <location line="+15" />
        <source>“%1” ships with the model and cannot be deleted</source>
        <translation>“%1” ships with the model and cannot be deleted</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot delete %1</source>
        <translation>cannot delete %1</translation>
    </message>
    <message>
        <location line="+5" />
        <source>there is no profile “%1”</source>
        <translation>there is no profile “%1”</translation>
    </message>
    <message>
        <location line="+26" />
        <source>%1 exists already</source>
        <translation>%1 exists already</translation>
    </message>
</context>
<context>
    <name>trainer::SdlJoysticks</name>
    <message>
        <location filename="../trainer/input/sdl_joysticks.cpp" line="+110" />
        <source>SDL cannot open it: %1</source>
        <translation>SDL cannot open it: %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>It has neither axes nor buttons, so it cannot drive a valve.</source>
        <translation>It has neither axes nor buttons, so it cannot drive a valve.</translation>
    </message>
    <message>
        <location line="+2" />
        <source>It has no axes, so it cannot drive a valve (its buttons can still be used).</source>
        <translation>It has no axes, so it cannot drive a valve (its buttons can still be used).</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Unplugged; waiting for it to come back</source>
        <translation>Unplugged; waiting for it to come back</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Unnamed gamepad</source>
        <translation>Unnamed gamepad</translation>
    </message>
    <message>
        <location line="+17" />
        <source>Unnamed joystick</source>
        <translation>Unnamed joystick</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Axis %1</source>
        <translation>Axis %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Button %1</source>
        <translation>Button %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Hat %1 up</source>
        <translation>Hat %1 up</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 right</source>
        <translation>Hat %1 right</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 down</source>
        <translation>Hat %1 down</translation>
    </message>
    <message>
        <location line="+1" />
        <source>Hat %1 left</source>
        <translation>Hat %1 left</translation>
    </message>
    <message>
        <location line="+29" />
        <source>Joysticks and gamepads cannot be used: SDL did not start (%1).</source>
        <translation>Joysticks and gamepads cannot be used: SDL did not start (%1).</translation>
    </message>
    <message>
        <location line="+9" />
        <source>Closed: the joystick back end was stopped</source>
        <translation>Closed: the joystick back end was stopped</translation>
    </message>
</context>
<context>
    <name>trainer::SerialDaq</name>
    <message>
        <location filename="../trainer/input/serial_daq.cpp" line="+40" />
        <location line="+223" />
        <source>DAQ console on %1</source>
        <translation>DAQ console on %1</translation>
    </message>
    <message>
        <location line="-208" />
        <source>device removed: %1</source>
        <translation>device removed: %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>read error or hang-up</source>
        <translation>read error or hang-up</translation>
    </message>
    <message>
        <location line="+2" />
        <source>write error</source>
        <translation>write error</translation>
    </message>
    <message>
        <location line="+49" />
        <source>The console on %1 is disconnected (%2); trying again every second.</source>
        <translation>The console on %1 is disconnected (%2); trying again every second.</translation>
    </message>
    <message>
        <location line="+4" />
        <source>Cannot open %1: %2. Trying again every second.</source>
        <translation>Cannot open %1: %2. Trying again every second.</translation>
    </message>
    <message>
        <location line="+27" />
        <source>The console on %1 was disconnected (%2); trying again every second.</source>
        <translation>The console on %1 was disconnected (%2); trying again every second.</translation>
    </message>
    <message>
        <location line="+82" />
        <source>No data from the console on %1 for %2 s.</source>
        <translation>No data from the console on %1 for %2 s.</translation>
    </message>
    <message>
        <location line="+51" />
        <source>Lever %1</source>
        <translation>Lever %1</translation>
    </message>
</context>
<context>
    <name>trainer::Station</name>
    <message>
        <location filename="../trainer/station/device_factory.cpp" line="+17" />
        <source>“serial:” needs a port name, e.g. serial:/dev/ttyACM0</source>
        <translation>“serial:” needs a port name, e.g. serial:/dev/ttyACM0</translation>
    </message>
    <message>
        <location line="+10" />
        <source>%1: this Padrob was built without Comedi (install libcomedi-dev and build again); the card is ignored</source>
        <translation>%1: this Padrob was built without Comedi (install libcomedi-dev and build again); the card is ignored</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: unknown kind of device; it is ignored</source>
        <translation>%1: unknown kind of device; it is ignored</translation>
    </message>
    <message>
        <location filename="../trainer/station/station.cpp" line="+116" />
        <source>the station is not running</source>
        <translation>the station is not running</translation>
    </message>
</context>
<context>
    <name>trainer::StationEngine</name>
    <message>
        <location filename="../trainer/station/station_engine.cpp" line="+444" />
        <source>not connected</source>
        <translation>not connected</translation>
    </message>
    <message>
        <location line="-12" />
        <source>valves closed, holding %1</source>
        <translation>valves closed, holding %1</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the keyboard drives %1 instead</source>
        <translation>the keyboard drives %1 instead</translation>
    </message>
    <message>
        <location line="+13" />
        <source>%1: %2 — %3</source>
        <translation>%1: %2 — %3</translation>
    </message>
    <message>
        <location line="+14" />
        <source>%1, %2: device fault, it reads %3 where it can read only %4…%5 — valve closed%6</source>
        <translation>%1, %2: device fault, it reads %3 where it can read only %4…%5 — valve closed%6</translation>
    </message>
    <message>
        <location line="+3" />
        <source>, holding %1</source>
        <translation>, holding %1</translation>
    </message>
    <message>
        <location line="+16" />
        <source>No %1 found — %2</source>
        <translation>No %1 found — %2</translation>
    </message>
    <message>
        <location line="+9" />
        <source>the keyboard drives instead</source>
        <translation>the keyboard drives instead</translation>
    </message>
    <message>
        <location line="+1" />
        <source>its valves are closed, the machine holds</source>
        <translation>its valves are closed, the machine holds</translation>
    </message>
    <message numerus="yes">
        <location line="+1" />
        <source>the keyboard drives %1 of its %n drive(s), the rest hold</source>
        <translation><numerusform>the keyboard drives %1 of its %n drive, the rest hold</numerusform><numerusform>the keyboard drives %1 of its %n drives, the rest hold</numerusform></translation>
    </message>
    <message>
        <location line="+3" />
        <source>%1 missing — %2</source>
        <translation>%1 missing — %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>%1: next bank</source>
        <translation>%1: next bank</translation>
    </message>
    <message>
        <location line="+7" />
        <source>Calibrating: every valve is held closed</source>
        <translation>Calibrating: every valve is held closed</translation>
    </message>
    <message>
        <location line="+3" />
        <source>Bring the lever to centre to take over: %1</source>
        <translation>Bring the lever to centre to take over: %1</translation>
    </message>
</context>
<context>
    <name>trainer::StationProfile</name>
    <message>
        <location filename="../trainer/station/profile.cpp" line="+48" />
        <location line="+8" />
        <source>“%1” is missing</source>
        <translation>“%1” is missing</translation>
    </message>
    <message>
        <location line="-7" />
        <source>“%1” must be a text</source>
        <translation>“%1” must be a text</translation>
    </message>
    <message>
        <location line="+10" />
        <source>“%1” must be a whole number</source>
        <translation>“%1” must be a whole number</translation>
    </message>
    <message>
        <location line="+8" />
        <source>“%1” must be a number</source>
        <translation>“%1” must be a number</translation>
    </message>
    <message>
        <location line="+8" />
        <source>“%1” must be a list</source>
        <translation>“%1” must be a list</translation>
    </message>
    <message>
        <location line="+6" />
        <source>must be an object { … }</source>
        <translation>must be an object { … }</translation>
    </message>
    <message>
        <location line="+34" />
        <source>line %1, column %2</source>
        <translation>line %1, column %2</translation>
    </message>
    <message>
        <location line="+94" />
        <source>not a valid profile file (%1); fix the JSON or import the profile again</source>
        <translation>not a valid profile file (%1); fix the JSON or import the profile again</translation>
    </message>
    <message>
        <location line="+6" />
        <source>not a station profile: the file must hold one JSON object</source>
        <translation>not a station profile: the file must hold one JSON object</translation>
    </message>
    <message>
        <location line="+5" />
        <source>not a station profile (“format” must be "%1")</source>
        <translation>not a station profile (“format” must be "%1")</translation>
    </message>
    <message>
        <location line="+8" />
        <source>made by a newer Padrob (profile version %1; this one reads up to %2). Update Padrob or use a profile saved by this version.</source>
        <translation>made by a newer Padrob (profile version %1; this one reads up to %2). Update Padrob or use a profile saved by this version.</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the version must be 1 or more</source>
        <translation>the version must be 1 or more</translation>
    </message>
    <message>
        <location line="+65" />
        <source>“%1” must be translated by a text</source>
        <translation>“%1” must be translated by a text</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the mapping names no device</source>
        <translation>the mapping names no device</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the axis must be 0 or more</source>
        <translation>the axis must be 0 or more</translation>
    </message>
    <message>
        <location line="+1" />
        <source>the sign must be 1 or -1</source>
        <translation>the sign must be 1 or -1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the gain must be between 0 and %1</source>
        <translation>the gain must be between 0 and %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>drive C %1 is not in this model (or has no D statement); this mapping is ignored</source>
        <translation>drive C %1 is not in this model (or has no D statement); this mapping is ignored</translation>
    </message>
    <message>
        <location line="+12" />
        <source>a bank button needs a device and a button number</source>
        <translation>a bank button needs a device and a button number</translation>
    </message>
    <message>
        <location line="+9" />
        <source>“%1”: only serial DAQ ports (serial:…) and Comedi cards (comedi:…) are listed here</source>
        <translation>“%1”: only serial DAQ ports (serial:…) and Comedi cards (comedi:…) are listed here</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the baud rate must be positive</source>
        <translation>the baud rate must be positive</translation>
    </message>
    <message>
        <location line="+11" />
        <source>Keyboard and gamepad</source>
        <translation>Keyboard and gamepad</translation>
    </message>
    <message>
        <location line="+2" />
        <source>Made by Padrob for this model: key pairs Q/A, W/S, … on the drives in order, and a two-stick gamepad in banks of four drives, switched with the shoulder buttons.</source>
        <translation>Made by Padrob for this model: key pairs Q/A, W/S, … on the drives in order, and a two-stick gamepad in banks of four drives, switched with the shoulder buttons.</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Bank %1</source>
        <translation>Bank %1</translation>
    </message>
    <message>
        <location line="+6" />
        <source>Bank 1</source>
        <translation>Bank 1</translation>
    </message>
</context>
<context>
    <name>trainer::records::RecordsDb</name>
    <message>
        <location filename="../trainer/records/records_db.cpp" line="+288" />
        <source>the records database is in use by another program, which has kept it locked for over %1 s; close that program or try again</source>
        <translation>the records database is in use by another program, which has kept it locked for over %1 s; close that program or try again</translation>
    </message>
    <message>
        <location line="+12" />
        <source>the records database %1 is read-only (check the permissions of the file and of its folder)</source>
        <translation>the records database %1 is read-only (check the permissions of the file and of its folder)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the disk holding the records database %1 is full; free some space (nothing of this step was recorded)</source>
        <translation>the disk holding the records database %1 is full; free some space (nothing of this step was recorded)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the records database %1 is damaged (%2); keep a copy of the file and restore it from a backup</source>
        <translation>the records database %1 is damaged (%2); keep a copy of the file and restore it from a backup</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the file is not a records database (not an SQLite database, or a damaged one)</source>
        <translation>the file is not a records database (not an SQLite database, or a damaged one)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>SQLite cannot open the file %1 (does its folder exist, and may Padrob write there?)</source>
        <translation>SQLite cannot open the file %1 (does its folder exist, and may Padrob write there?)</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the disk reported an error on %1 (%2)</source>
        <translation>the disk reported an error on %1 (%2)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>the PostgreSQL server's disk is full; ask its administrator to free some space (nothing of this step was recorded)</source>
        <translation>the PostgreSQL server's disk is full; ask its administrator to free some space (nothing of this step was recorded)</translation>
    </message>
    <message>
        <location line="+3" />
        <location line="+31" />
        <source>the records database %1 is open read-only</source>
        <translation>the records database %1 is open read-only</translation>
    </message>
    <message>
        <location line="-29" />
        <source>the PostgreSQL user may not do this on %1 (%2); ask the server's administrator for the rights</source>
        <translation>the PostgreSQL user may not do this on %1 (%2); ask the server's administrator for the rights</translation>
    </message>
    <message>
        <location line="+4" />
        <source>lost the connection to the PostgreSQL server %1 (%2)</source>
        <translation>lost the connection to the PostgreSQL server %1 (%2)</translation>
    </message>
    <message>
        <location line="+8" />
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+11" />
        <source>the records database is not open</source>
        <translation>the records database is not open</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the records database was opened in another thread (each thread needs a RecordsDb of its own)</source>
        <translation>the records database was opened in another thread (each thread needs a RecordsDb of its own)</translation>
    </message>
    <message>
        <location line="+73" />
        <location line="+58" />
        <location line="+60" />
        <source>cannot open the records database %1</source>
        <translation>cannot open the records database %1</translation>
    </message>
    <message>
        <location line="-115" />
        <source>the SQLite driver of Qt (QSQLITE) is not installed (on Debian: the package libqt6sql6-sqlite)</source>
        <translation>the SQLite driver of Qt (QSQLITE) is not installed (on Debian: the package libqt6sql6-sqlite)</translation>
    </message>
    <message>
        <location line="+7" />
        <source>it is a folder, not a file</source>
        <translation>it is a folder, not a file</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the file is not a records database (not an SQLite database)</source>
        <translation>the file is not a records database (not an SQLite database)</translation>
    </message>
    <message>
        <location line="+2" />
        <source>there is no such file</source>
        <translation>there is no such file</translation>
    </message>
    <message>
        <location line="+4" />
        <source>cannot create its folder %1</source>
        <translation>cannot create its folder %1</translation>
    </message>
    <message>
        <location line="+3" />
        <source>the file is read-only (check its permissions, or open the records read-only)</source>
        <translation>the file is read-only (check its permissions, or open the records read-only)</translation>
    </message>
    <message>
        <location line="+3" />
        <source>its folder %1 is read-only, and SQLite writes its journal there (check the folder's permissions, or open the records read-only)</source>
        <translation>its folder %1 is read-only, and SQLite writes its journal there (check the folder's permissions, or open the records read-only)</translation>
    </message>
    <message>
        <location line="+32" />
        <source>the PostgreSQL driver of Qt (QPSQL) is not installed (on Debian: the package libqt6sql6-psql); until it is, use the records file on this computer</source>
        <translation>the PostgreSQL driver of Qt (QPSQL) is not installed (on Debian: the package libqt6sql6-psql); until it is, use the records file on this computer</translation>
    </message>
    <message>
        <location line="+15" />
        <source>the PostgreSQL server did not accept the connection (%1)</source>
        <translation>the PostgreSQL server did not accept the connection (%1)</translation>
    </message>
    <message>
        <location line="+32" />
        <source>it holds other tables, not Padrob's records (left untouched)</source>
        <translation>it holds other tables, not Padrob's records (left untouched)</translation>
    </message>
    <message>
        <location line="+16" />
        <source>it has schema version %1, newer than this Padrob's (%2); open it with a newer Padrob (it was left untouched)</source>
        <translation>it has schema version %1, newer than this Padrob's (%2); open it with a newer Padrob (it was left untouched)</translation>
    </message>
    <message>
        <location line="+14" />
        <source>it holds no records yet, and it is open read-only</source>
        <translation>it holds no records yet, and it is open read-only</translation>
    </message>
    <message>
        <location line="+1" />
        <source>it has the older schema version %1 and this Padrob needs %2; open it once with write access to upgrade it</source>
        <translation>it has the older schema version %1 and this Padrob needs %2; open it once with write access to upgrade it</translation>
    </message>
    <message>
        <location line="+14" />
        <source>SQLite refused the write-ahead log (journal mode %1)</source>
        <translation>SQLite refused the write-ahead log (journal mode %1)</translation>
    </message>
    <message>
        <location line="+37" />
        <source>the upgrade to schema version %1 failed (%2)</source>
        <translation>the upgrade to schema version %1 failed (%2)</translation>
    </message>
    <message>
        <location line="+224" />
        <location line="+470" />
        <source>cannot add the operator “%1”</source>
        <translation>cannot add the operator “%1”</translation>
    </message>
    <message>
        <location line="-468" />
        <location line="+470" />
        <source>an operator needs an id</source>
        <translation>an operator needs an id</translation>
    </message>
    <message>
        <location line="-464" />
        <source>the id is taken already, by “%1”</source>
        <translation>the id is taken already, by “%1”</translation>
    </message>
    <message>
        <location line="+14" />
        <source>cannot rename the operator</source>
        <translation>cannot rename the operator</translation>
    </message>
    <message>
        <location line="+7" />
        <location line="+31" />
        <source>there is no operator %1</source>
        <translation>there is no operator %1</translation>
    </message>
    <message>
        <location line="-25" />
        <source>cannot look the operator up</source>
        <translation>cannot look the operator up</translation>
    </message>
    <message>
        <location line="+15" />
        <source>cannot record the start of the attempt</source>
        <translation>cannot record the start of the attempt</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the tutorial has no id</source>
        <translation>the tutorial has no id</translation>
    </message>
    <message>
        <location line="+33" />
        <source>cannot record the attempt's events</source>
        <translation>cannot record the attempt's events</translation>
    </message>
    <message>
        <location line="+4" />
        <source>an event has no valid time</source>
        <translation>an event has no valid time</translation>
    </message>
    <message>
        <location line="+5" />
        <location line="+54" />
        <location line="+275" />
        <source>there is no attempt %1</source>
        <translation>there is no attempt %1</translation>
    </message>
    <message>
        <location line="-300" />
        <source>cannot record the attempt's result</source>
        <translation>cannot record the attempt's result</translation>
    </message>
    <message>
        <location line="+5" />
        <source>the score %1 is not within 0…100</source>
        <translation>the score %1 is not within 0…100</translation>
    </message>
    <message>
        <location line="+2" />
        <source>%1 stars is not within 0…3</source>
        <translation>%1 stars is not within 0…3</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the duration %1 s is not valid</source>
        <translation>the duration %1 s is not valid</translation>
    </message>
    <message>
        <location line="+4" />
        <source>the score breakdown has an empty or repeated key “%1”</source>
        <translation>the score breakdown has an empty or repeated key “%1”</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the score item “%1” has no valid value or points</source>
        <translation>the score item “%1” has no valid value or points</translation>
    </message>
    <message>
        <location line="+37" />
        <source>cannot read the operators' progress</source>
        <translation>cannot read the operators' progress</translation>
    </message>
    <message>
        <location line="+59" />
        <source>cannot read the operator's attempts</source>
        <translation>cannot read the operator's attempts</translation>
    </message>
    <message>
        <location line="+7" />
        <location line="+96" />
        <location line="+82" />
        <source>cannot read the attempt</source>
        <translation>cannot read the attempt</translation>
    </message>
    <message>
        <location line="-165" />
        <source>cannot export the records to %1</source>
        <translation>cannot export the records to %1</translation>
    </message>
    <message>
        <location line="-191" />
        <source>there is an attempt with the id %1 already</source>
        <translation>there is an attempt with the id %1 already</translation>
    </message>
    <message>
        <location line="+63" />
        <source>an attempt ends finished, aborted or interrupted, not %1</source>
        <translation>an attempt ends finished, aborted or interrupted, not %1</translation>
    </message>
    <message>
        <location line="+226" />
        <source>cannot read what the centre's server lacks</source>
        <translation>cannot read what the centre's server lacks</translation>
    </message>
    <message>
        <location line="+44" />
        <location line="+12" />
        <source>cannot note what the centre's server has</source>
        <translation>cannot note what the centre's server has</translation>
    </message>
    <message>
        <location line="+22" />
        <source>cannot give the old attempts their unique ids</source>
        <translation>cannot give the old attempts their unique ids</translation>
    </message>
    <message>
        <location line="+18" />
        <source>cannot read the attempt's events</source>
        <translation>cannot read the attempt's events</translation>
    </message>
    <message>
        <location line="+39" />
        <source>cannot copy the attempt %1</source>
        <translation>cannot copy the attempt %1</translation>
    </message>
    <message>
        <location line="+2" />
        <source>the attempt has no unique id</source>
        <translation>the attempt has no unique id</translation>
    </message>
    <message>
        <location line="+62" />
        <source>an event has no index</source>
        <translation>an event has no index</translation>
    </message>
    <message>
        <location line="+18" />
        <source>cannot reach the records database</source>
        <translation>cannot reach the records database</translation>
    </message>
</context>
<context>
    <name>trainer::records::SharedRecords</name>
    <message>
        <location filename="../trainer/records/shared_records.cpp" line="+165" />
        <source>cannot send the records to the centre's server: the station's records are not open</source>
        <translation>cannot send the records to the centre's server: the station's records are not open</translation>
    </message>
    <message>
        <location line="+104" />
        <source>not connected yet to the centre's records server %1: this station records on its own until it is</source>
        <translation>not connected yet to the centre's records server %1: this station records on its own until it is</translation>
    </message>
    <message>
        <location line="+3" />
        <source>this station records on its own, and sends its records to the centre's server %1 when it is back (%2)</source>
        <translation>this station records on its own, and sends its records to the centre's server %1 when it is back (%2)</translation>
    </message>
</context>
</TS>
