/*
 * Mesh: cloths, plates, jellies and a ball, each built in a few lines by
 * TopoGenerator and drawn in 3D in one call by ModelRenderer. The scene changes
 * every 1.5 seconds, and each holds its mesh with a different boundary
 * condition (every Bound of the generator); links turn red as they stretch.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel; gravity pulls toward -z, which is
 * drawn downward.
 */

import tactus.*;

PhysicalModel mdl;
ModelRenderer renderer;
int simRate = 1000;
int dispRate = 60;
int scene = -1;
int sceneFrames = 90;       // frames per scene when nobody presses a key
int sceneStart = 0;
String sceneName = "";
boolean showMasses = true;  // key M
float zoomZ = 1;            // key Z
float spin = 0;

String[] names = {
  "a cloth held by one edge (Bound.Y_RIGHT)",
  "a plate clamped at its left end (Bound.X_LEFT)",
  "a plate clamped at its right end, turned 30 degrees (Bound.X_RIGHT)",
  "a trampoline held by its corners (Bound.FIXED_CORNERS)",
  "a cloth held by the other edge (Bound.Y_LEFT)",
  "a jelly standing on its bottom face (Bound.Z_LEFT)",
  "a jelly hanging from its top face (Bound.Z_RIGHT)",
  "a ball pinned at its centre (Bound.FIXED_CENTRE, carved by conditionAlongSphere)"
};

void setup() {
  size(900, 600, P3D);
  frameRate(dispRate);
  renderer = new ModelRenderer(this);
  renderer.setColor(matModuleType.Mass3D, 230, 150, 40);
  renderer.setSize(matModuleType.Mass3D, 2);
  renderer.setScaling(matModuleType.Mass3D, 1.5);   // radius 2 + 1.5 x mass
  renderer.setColor(matModuleType.Ground3D, 60, 60, 60);
  renderer.setSize(matModuleType.Ground3D, 4);
  renderer.setColor(linkModuleType.SpringDamper3D, 40, 120, 200, 200);
  renderer.setSize(linkModuleType.SpringDamper3D, 1);
  renderer.setStrainColor(linkModuleType.SpringDamper3D, 230, 30, 30, 255);
  renderer.setStrainGradient(linkModuleType.SpringDamper3D, true, 0.08);
  renderer.setScale(1.5);                           // every drawn coordinate and radius x 1.5
  nextScene();
}

void nextScene() {
  scene = (scene + 1) % names.length;
  sceneName = names[scene];
  sceneStart = frameCount;
  mdl = new PhysicalModel(simRate, dispRate);
  mdl.setGravity(0.0002);
  mdl.setFriction(0.0005);
  switch (scene) {
  case 0:
    generate(10, 10, 1, 0, Bound.Y_RIGHT);
    break;
  case 1:
    generate(12, 4, 2, 0, Bound.X_LEFT);
    break;
  case 2:
    generate(12, 4, 2, PI / 6, Bound.X_RIGHT);
    break;
  case 3:
    generate(9, 9, 1, 0, Bound.FIXED_CORNERS);
    break;
  case 4:
    generate(10, 10, 1, 0, Bound.Y_LEFT);
    break;
  case 5:
    generate(4, 4, 4, 0, Bound.Z_LEFT);
    break;
  case 6:
    generate(4, 4, 4, 0, Bound.Z_RIGHT);
    break;
  default:
    generate(5, 5, 5, 0, Bound.FIXED_CENTRE);
    break;
  }
  mdl.init();
  kick();
}

// One block of masses on a grid, every neighbour within one step linked by a spring-damper.
void generate(int dx, int dy, int dz, float turn, Bound held) {
  float spacing = 25;
  TopoGenerator gen = new TopoGenerator(mdl, "m", "s");
  gen.setDim(dx, dy, dz, 1);
  gen.set2DPlane(false);                        // free 3D masses
  gen.setParams(1, 0.02, 0.001);                // mass, stiffness, damping
  gen.setGeometry(spacing, spacing);            // grid spacing, rest length of a one-step link
  gen.setRotation(0, 0, turn);                  // about x, then y, then z, around the grid's origin
  gen.setTranslation(-spacing * (dx - 1) / 2, -spacing * (dy - 1) / 2, -spacing * (dz - 1) / 2);
  gen.setMatSubsetName("meshMasses");
  gen.setLinkSubsetName("meshLinks");
  gen.addBoundaryCondition(held);
  gen.generate();
  if (held == Bound.FIXED_CENTRE) {
    gen.conditionAlongSphere(spacing * 2.1, true); // keep only the masses within this radius of the centre
  }
}

// Push every free mass a little, sideways and up, so that each scene starts moving.
void kick() {
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    if (mdl.getMatTypeAt(i) == matModuleType.Mass3D) {
      Vect3D p = mdl.getMatPosAt(i);
      mdl.triggerForceImpulse(i, 0.02 * p.y() / 100, 0, 0.08);
    }
  }
}

void draw() {
  if (frameCount - sceneStart >= sceneFrames) {
    nextScene();
  }
  mdl.draw_physics();
  spin += 0.004;

  background(245);
  lights();
  pushMatrix();
  translate(width / 2, height / 2 + 40, 0);
  rotateX(1.1);              // z points up on the screen
  rotateZ(0.6 + spin);
  renderer.renderModel(mdl);
  popMatrix();
  noLights();

  hint(DISABLE_DEPTH_TEST);
  camera();
  fill(20);
  textSize(14);
  textAlign(LEFT, TOP);
  text((scene + 1) + "/" + names.length + ": " + sceneName, 12, 12);
  text(mdl.getNumberOfMats() + " masses, " + mdl.getNumberOfLinks() + " links, stiffness "
    + nf((float) mdl.getParamValueOfSubset("meshLinks", "stiffness"), 0, 3), 12, 32);
  text("SPACE: next scene   K: kick   M: masses " + (showMasses ? "on" : "off") + "   +/-: scale "
    + nf(renderer.getScale(), 0, 2) + "   Z: stretch z x" + nf(zoomZ, 0, 0), 12, height - 24);
  hint(ENABLE_DEPTH_TEST);
}

void keyPressed() {
  if (key == ' ') {
    nextScene();
  } else if (key == 'k' || key == 'K') {
    kick();
  } else if (key == 'm' || key == 'M') {
    showMasses = !showMasses;
    renderer.displayMats(showMasses);
  } else if (key == '+' || key == '=') {
    renderer.setScale(min(renderer.getScale() * 1.25, 4));
  } else if (key == '-') {
    renderer.setScale(max(renderer.getScale() / 1.25, 0.25));
  } else if (key == 'z' || key == 'Z') {
    zoomZ = zoomZ >= 3 ? 1 : zoomZ + 1;
    renderer.setZoomVector(1, 1, zoomZ);
  }
}
