/*
 * PluckedString3D: a string of 30 masses stretched across the workspace. Hook it with your
 * hand, pull it up, down or towards you, and let go: it rings in both directions across it.
 *
 * Device: an Inverse3 through the Inverse Service, else a 2DIY board, else the emulated
 * Inverse3 with the mouse as your hand.
 * Controls: T print the loop's telemetry; R let the string ring freely (the hand passes through).
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, parameters per step of the 1 kHz haptic loop.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession3D haptics;
int n = 30;
int avatar;
boolean touching = true;

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  haptics = HapticSession3D.open(this);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0002);
  mdl.addHapticInput3D("avatar", haptics.home(), 10);
  float x0 = width / 2 - 300;
  float step = 600.0 / (n + 1);
  mdl.addGround3D("left", new Vect3D(x0, height / 2, 0));
  for (int i = 1; i <= n; i++) {
    mdl.addMass3D("m" + i, 1, new Vect3D(x0 + i * step, height / 2, 0), new Vect3D());
  }
  mdl.addGround3D("right", new Vect3D(x0 + (n + 1) * step, height / 2, 0));
  for (int i = 0; i <= n; i++) {
    String a = i == 0 ? "left" : "m" + i;
    String b = i == n ? "right" : "m" + (i + 1);
    mdl.addSpringDamper3D("s" + i, step * 0.8, 0.1, 0.0005, a, b);   // stretched: 20 % above rest length
  }
  for (int i = 1; i <= n; i++) {
    mdl.addContact3D("pick" + i, 14, 0.02, 0.001, "avatar", "m" + i);
  }
  mdl.init();
  avatar = mdl.getMatIndex("avatar");

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(3);
  loop.start();
}

void draw() {
  background(20, 24, 32);
  lights();
  ModelSnapshot s = mdl.getSnapshot();
  pushMatrix();
  translate(width / 2, height / 2, 0);
  rotateX(-0.45);
  rotateY(0.35);
  translate(-width / 2, -height / 2, 0);
  stroke(240, 200, 90);
  strokeWeight(3);
  noFill();
  beginShape();
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    if (i != avatar) {
      vertex((float) s.x(i), (float) s.y(i), (float) s.z(i));
    }
  }
  endShape();
  noStroke();
  fill(touching ? color(230, 70, 60) : color(120));
  pushMatrix();
  translate((float) s.x(avatar), (float) s.y(avatar), (float) s.z(avatar));
  sphere(8);
  // the plectrum's reach (its contacts act within 14 px) and its handle
  noFill();
  stroke(touching ? color(230, 70, 60) : color(160), 180);
  strokeWeight(2);
  ellipse(0, 0, 28, 28);
  strokeWeight(3);
  line(0, 0, 0, 0, -40, 0);
  noStroke();
  popMatrix();
  popMatrix();
  fill(230);
  textSize(14);
  text("Hook the string and let go.   R: " + (touching ? "let it ring" : "touch again") + "   T: telemetry", 12, 22);
  text(haptics.telemetryLine(), 12, 42);
  haptics.drawStatus();
}

void keyPressed() {
  if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  } else if (key == 'r' || key == 'R') {
    touching = !touching;
    for (int i = 1; i <= n; i++) {
      mdl.setLinkStiffness("pick" + i, touching ? 0.02 : 0);
    }
  }
}
