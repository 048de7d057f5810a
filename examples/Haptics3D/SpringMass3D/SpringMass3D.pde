/*
 * SpringMass3D: a heavy ball hangs on a spring in space; push it with your hand in any
 * direction and feel it swing back, in three dimensions.
 *
 * Device: an Inverse3 (or Inverse3x, Minverse) through the Haply Hub's Inverse Service if one
 * is there, else a 2DIY board (x and y only), else the emulated Inverse3 with the mouse as
 * your hand (its depth swings slowly on its own).
 * Controls: T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel (x right, y down, z towards you), parameters per
 * step of the 1 kHz haptic loop; 1 model force unit = 1 N at the hand.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession3D haptics;
double[] force = new double[3];
int avatar;
int ball;

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  haptics = HapticSession3D.open(this);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0005);
  mdl.addHapticInput3D("avatar", haptics.home(), 10);
  mdl.addGround3D("hook", new Vect3D(width / 2, height / 2 - 150, 0));
  mdl.addMass3D("ball", 30, new Vect3D(width / 2, height / 2, 0), new Vect3D());
  mdl.addSpringDamper3D("spring", 100, 0.002, 0.02, "hook", "ball");
  mdl.addContact3D("touch", 38, 0.05, 0.01, "avatar", "ball");
  mdl.init();
  avatar = mdl.getMatIndex("avatar");
  ball = mdl.getMatIndex("ball");

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(2);
  loop.start();
}

void draw() {
  background(245);
  lights();
  ModelSnapshot s = mdl.getSnapshot();
  pushMatrix();
  // a slight turn so that depth shows
  translate(width / 2, height / 2, 0);
  rotateX(-0.3);
  rotateY(0.4);
  translate(-width / 2, -height / 2, 0);
  stroke(120);
  strokeWeight(2);
  line(width / 2, height / 2 - 150, 0, (float) s.x(ball), (float) s.y(ball), (float) s.z(ball));
  noStroke();
  drawSphere(s, ball, 26, color(40, 90, 200));
  drawSphere(s, avatar, 12, color(220, 50, 40));
  popMatrix();

  haptics.forceInModel(force);
  fill(30);
  textSize(14);
  text(String.format("force %.2f N   %s   T: telemetry", Math.sqrt(force[0] * force[0] + force[1] * force[1]
      + force[2] * force[2]), haptics.telemetryLine()), 12, 22);
  haptics.drawStatus();
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
    haptics.loop().printTelemetry();
  }
}
