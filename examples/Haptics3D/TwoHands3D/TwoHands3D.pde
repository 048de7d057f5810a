/*
 * TwoHands3D: a ball hangs on a spring between your two hands; push it from the left with one
 * Inverse3 and from the right with the other, and feel each push in the other hand too.
 *
 * Devices: a left-handed and a right-handed Inverse3 through the Haply Hub's Inverse Service if
 * it lists both, else the emulator serving two Inverse3s, the mouse moving the right hand and the
 * left hand as its mirror image (both tour the workspace until the mouse moves).
 * Controls: T print both loops' telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel (x right, y down, z towards you), parameters per
 * step of the 1 kHz haptic loop; 1 model force unit = 1 N at each hand.
 */

import tactus.*;
import tactus.haptics.*;
import tactus.haptics.inverse.*;

PhysicalModel mdl;
HapticSession3D left;
HapticSession3D right;
double[] forceL = new double[3];
double[] forceR = new double[3];
int avatarL;
int avatarR;
int ball;

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  try {
    left = HapticSession3D.open(this, Inverse3Choice.byHandedness("left"));
    right = HapticSession3D.open(this, Inverse3Choice.byHandedness("right"));
  } catch (HaplyLinkException e) {
    println("Two Inverse3s not found (" + e.getMessage() + "): the emulator serves two");
    if (left != null) {
      left.close();
    }
    HapticSession3D[] pair = HapticSession3D.openEmulatedPair(this);
    left = pair[0];
    right = pair[1];
  }

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0005);
  mdl.addHapticInput3D("left", left.home(), 10);
  mdl.addHapticInput3D("right", right.home(), 10);
  mdl.addGround3D("hook", new Vect3D(width / 2, height / 2 - 150, 0));
  mdl.addMass3D("ball", 30, new Vect3D(width / 2, height / 2, 0), new Vect3D());
  mdl.addSpringDamper3D("spring", 100, 0.002, 0.02, "hook", "ball");
  mdl.addContact3D("touchL", 38, 0.05, 0.01, "left", "ball");
  mdl.addContact3D("touchR", 38, 0.05, 0.01, "right", "ball");
  mdl.init();
  avatarL = mdl.getMatIndex("left");
  avatarR = mdl.getMatIndex("right");
  ball = mdl.getMatIndex("ball");

  // the right hand's loop steps the model; the left hand's loop only moves its avatar and takes its force
  HapticLoop loopR = right.attach(mdl, "right");
  loopR.setForceGain(2);
  HapticLoop loopL = left.attach(mdl, "left");
  loopL.setForceGain(2);
  loopL.setMode(HapticLoop.Mode.AUDIO);
  loopR.start();
  loopL.start();
}

void draw() {
  background(245);
  lights();
  ModelSnapshot s = mdl.getSnapshot();
  pushMatrix();
  translate(width / 2, height / 2, 0);
  rotateX(-0.3);
  rotateY(0.4);
  translate(-width / 2, -height / 2, 0);
  stroke(120);
  strokeWeight(2);
  line(width / 2, height / 2 - 150, 0, (float) s.x(ball), (float) s.y(ball), (float) s.z(ball));
  noStroke();
  drawSphere(s, ball, 26, color(40, 90, 200));
  drawSphere(s, avatarL, 12, color(30, 160, 70));
  drawSphere(s, avatarR, 12, color(220, 50, 40));
  popMatrix();

  left.forceInModel(forceL);
  right.forceInModel(forceR);
  fill(30);
  textSize(14);
  text(String.format("left %.2f N   right %.2f N   T: telemetry", norm(forceL), norm(forceR)), 12, 22);
  right.drawStatus();
}

double norm(double[] f) {
  return Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
}

void drawSphere(ModelSnapshot s, int i, float r, int c) {
  pushMatrix();
  translate((float) s.x(i), (float) s.y(i), (float) s.z(i));
  fill(c);
  sphere(r);
  popMatrix();
}

void keyPressed() {
  if (key == 't' || key == 'T') {
    left.loop().printTelemetry();
    right.loop().printTelemetry();
  }
}
