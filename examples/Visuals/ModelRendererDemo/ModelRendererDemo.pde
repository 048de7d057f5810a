/*
 * ModelRendererDemo: a drumhead of masses and spring-dampers, fixed along its
 * edges and stretched a little, drawn in one call by ModelRenderer, the
 * generic renderer.
 * The springs turn red as they stretch (strain colouring), and every style and
 * view setting used below can be changed while it runs, with the keys shown on
 * screen. Drag the mouse to turn the membrane, press SPACE to strike it.
 *
 * Units: ALGO_UNITS, the paper's choice; 1 model unit = 1 pixel.
 */

import tactus.*;

PhysicalModel mdl;
ModelRenderer renderer;

int simRate = 1000;   // physics steps per second
int dispRate = 60;    // frames per second
int n = 13;           // masses per side
float spacing = 25;   // distance between neighbours, model units
float restLength = 24; // spring length parameter: a strain of 1/24 at rest
float strainMax = 0.15; // strain at which a spring is drawn fully red

// view and style state, changed by the keys
boolean showMasses = true;
boolean strainColours = true;
float scale = 1;
float zoomZ = 1;
float rotX = 1.0;
float rotZ = 0.5;

void setup() {
  size(900, 700, P3D);
  frameRate(dispRate);

  mdl = new PhysicalModel(simRate, dispRate, paramSystem.ALGO_UNITS);
  mdl.setGravity(0.0001);   // pulls toward -z
  mdl.setFriction(0.0005);

  // The membrane in the x-y plane, centred on the origin; the edges are fixed.
  float offset = -spacing * (n - 1) / 2;
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      Vect3D pos = new Vect3D(offset + i * spacing, offset + j * spacing, 0);
      boolean edge = i == 0 || i == n - 1 || j == 0 || j == n - 1;
      if (edge) {
        mdl.addGround3D(massName(i, j), pos);
      } else {
        mdl.addMass3D(massName(i, j), 1, pos, new Vect3D(0, 0, 0));
      }
    }
  }
  // name, rest length, stiffness K, damping Z, first mass, second mass.
  // The rest length is a little shorter than the spacing: the membrane is under tension.
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      if (i + 1 < n) {
        mdl.addSpringDamper3D("h_" + i + "_" + j, restLength, 0.1, 0.001, massName(i, j), massName(i + 1, j));
      }
      if (j + 1 < n) {
        mdl.addSpringDamper3D("v_" + i + "_" + j, restLength, 0.1, 0.001, massName(i, j), massName(i, j + 1));
      }
    }
  }
  mdl.init();

  renderer = new ModelRenderer(this);
  renderer.setColor(matModuleType.Mass3D, 220, 140, 40);
  renderer.setSize(matModuleType.Mass3D, 4);
  renderer.setColor(matModuleType.Ground3D, 40, 200, 120);
  renderer.setSize(matModuleType.Ground3D, 5);
  renderer.setColor(linkModuleType.SpringDamper3D, 40, 160, 220, 255);
  renderer.setSize(linkModuleType.SpringDamper3D, 2);
  renderer.setStrainColor(linkModuleType.SpringDamper3D, 255, 40, 40, 255);
  renderer.setStrainGradient(linkModuleType.SpringDamper3D, strainColours, strainMax);
}

String massName(int i, int j) {
  return "m_" + i + "_" + j;
}

void draw() {
  mdl.draw_physics();

  background(250);
  lights();
  pushMatrix();
  translate(width / 2, height / 2, 0);
  rotateX(rotX);
  rotateZ(rotZ);
  renderer.renderModel(mdl);
  popMatrix();
  noLights();

  drawHelp();
}

void mouseDragged() {
  rotZ += (mouseX - pmouseX) * 0.01;
  rotX -= (mouseY - pmouseY) * 0.01;
}

void keyPressed() {
  if (key == ' ') {
    // strike a mass near the middle, downward (toward -z)
    mdl.triggerForceImpulse(massName(n / 2, n / 3), 0, 0, -15);
  } else if (key == 'm' || key == 'M') {
    showMasses = !showMasses;
    renderer.displayMats(showMasses);
  } else if (key == 's' || key == 'S') {
    strainColours = !strainColours;
    renderer.setStrainGradient(linkModuleType.SpringDamper3D, strainColours, strainMax);
  } else if (key == '+' || key == '=') {
    scale = min(scale * 1.25, 4);
    renderer.setScale(scale);
  } else if (key == '-') {
    scale = max(scale / 1.25, 0.25);
    renderer.setScale(scale);
  } else if (key == 'z' || key == 'Z') {
    // exaggerate the vertical motion: zoom 1, 3, 6, then back to 1
    zoomZ = zoomZ >= 6 ? 1 : (zoomZ == 1 ? 3 : 6);
    renderer.setZoomVector(1, 1, zoomZ);
  }
}

void drawHelp() {
  // Text in screen coordinates, on top of the 3D scene.
  hint(DISABLE_DEPTH_TEST);
  camera();
  fill(30);
  textSize(14);
  textAlign(LEFT, TOP);
  text("ModelRenderer: " + mdl.getNumberOfMats() + " masses, " + mdl.getNumberOfLinks() + " links", 12, 12);
  text("drag: turn    SPACE: strike the membrane", 12, 34);
  text("M: masses " + (showMasses ? "on" : "off")
    + "    S: strain colours " + (strainColours ? "on" : "off")
    + "    +/-: scale " + nf(scale, 1, 2)
    + "    Z: vertical zoom x" + nf(zoomZ, 1, 0), 12, 56);
  hint(ENABLE_DEPTH_TEST);
}
