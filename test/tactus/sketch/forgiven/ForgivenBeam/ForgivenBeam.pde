/*
 * ForgivenBeam: written the way the paper's BeamStress and DynamicParameterMods were, with the mistakes the paper's
 * engine silently ignored:
 * - the mass subset of a TopoGenerator includes its boundary masses, which are grounds, and a key changes the mass
 *   of the whole subset (the grounds are left alone, the other masses change);
 * - the mass of every module is printed, grounds included (a ground answers 1).
 * Tactus runs it as the original did, with one warning for this kind of problem (ForgivenSketchesTest).
 * Keys: W gives the beam random masses, X random stiffnesses, M prints every mass.
 */

import tactus.*;

PhysicalModel mdl;
int dimX = 10;
float zoom = 30;

void setup() {
  size(480, 360);
  frameRate(60);

  mdl = new PhysicalModel(600, 60);
  mdl.setGravity(0.0005);
  mdl.setFriction(0.0001);

  TopoGenerator q = new TopoGenerator(mdl, "mass", "spring");
  q.setDim(dimX, 2, 2, 1);
  q.setParams(1, 0.05, 0.003);
  q.setGeometry(1, 1);
  q.setMatSubsetName("beamMats");
  q.setLinkSubsetName("beamLinks");
  q.addBoundaryCondition(Bound.X_LEFT);
  q.generate();

  mdl.init();

  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    println("Mass = " + mdl.getMatMassAt(i) + ", ");
  }
}

void draw() {
  mdl.draw_physics();

  background(240);
  fill(0);
  text("mass of the first module: " + mdl.getMatMassAt(0), 10, 20);
  translate(60, height/3);
  noStroke();
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    PVector p = mdl.getMatPosAt(i).toPVector();
    if (mdl.getMatTypeAt(i) == matModuleType.Ground3D) fill(80);
    else fill(40, 120, 220);
    ellipse(p.x * zoom, -p.z * zoom, 10, 10);
  }
}

void keyPressed() {
  if (key == 'w') {
    mdl.changeMassParamOfSubset(random(10) + 1, "beamMats");
  }
  if (key == 'x') {
    mdl.changeStiffnessParamOfSubset(random(0.05) + 0.01, "beamLinks");
  }
  if (key == 'm') {
    for (int i = 0; i < mdl.getNumberOfMats(); i++) {
      println("Mass = " + mdl.getMatMassAt(i) + ", ");
    }
  }
}
