/*
 * VerseGripGrab: five blocks float in space. Bring your hand to one and hold the VerseGrip's
 * button (or press the mouse) to grab it: it hangs from your hand on a spring and you feel its
 * weight and its swing; let go to drop it. The grip's orientation turns the hand's pointer.
 *
 * Device: an Inverse3 with a VerseGrip through the Inverse Service, else a 2DIY board, else
 * the emulated Inverse3 with the mouse as your hand (the mouse button grabs).
 * Controls: mouse button or VerseGrip button A grab; T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, parameters per step of the 1 kHz haptic loop.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession3D haptics;
int blocks = 5;
int avatar;
int held = -1;
double[] q = new double[4];

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  haptics = HapticSession3D.open(this);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.001);
  mdl.setGravity(0.005);            // pixels per step squared: a block weighs about 0.1 N in the hand
  mdl.setGravityDirection(new Vect3D(0, -1, 0));   // y down the window: things fall down
  mdl.addHapticInput3D("avatar", haptics.home(), 10);
  for (int i = 0; i < blocks; i++) {
    float x = width / 2 + (i - 2) * 80;
    mdl.addGround3D("rest" + i, new Vect3D(x, height / 2 + 60, 0));
    mdl.addMass3D("block" + i, 10, new Vect3D(x, height / 2 + 60, 0), new Vect3D());
    mdl.addSpringDamper3D("shelf" + i, 0, 0.01, 0.05, "rest" + i, "block" + i);   // each rests on its place
    mdl.addSpringDamper3D("grab" + i, 0, 0, 0, "avatar", "block" + i);            // off until grabbed
  }
  mdl.init();
  avatar = mdl.getMatIndex("avatar");

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(2);
  loop.start();
}

void draw() {
  boolean pressing = haptics.button(0) || mousePressed;
  ModelSnapshot s = mdl.getSnapshot();
  if (pressing && held < 0) {
    held = nearest(s, 60);
    if (held >= 0) {
      mdl.setLinkStiffness("shelf" + held, 0);
      mdl.setLinkDamping("shelf" + held, 0);
      mdl.setLinkStiffness("grab" + held, 0.003);
      mdl.setLinkDamping("grab" + held, 0.02);
    }
  } else if (!pressing && held >= 0) {
    mdl.setLinkStiffness("grab" + held, 0);
    mdl.setLinkDamping("grab" + held, 0);
    mdl.setLinkStiffness("shelf" + held, 0.01);
    mdl.setLinkDamping("shelf" + held, 0.05);
    held = -1;
  }

  background(240);
  lights();
  pushMatrix();
  translate(width / 2, height / 2, 0);
  rotateX(-0.35);
  rotateY(0.3);
  translate(-width / 2, -height / 2, 0);
  noStroke();
  for (int i = 0; i < blocks; i++) {
    int m = mdl.getMatIndex("block" + i);
    pushMatrix();
    translate((float) s.x(m), (float) s.y(m), (float) s.z(m));
    fill(i == held ? color(240, 160, 40) : color(70, 110, 190));
    box(34);
    popMatrix();
  }
  // the hand, turned by the VerseGrip (identity without one)
  haptics.gripOrientation(q);
  pushMatrix();
  translate((float) s.x(avatar), (float) s.y(avatar), (float) s.z(avatar));
  // the reach of a grab: a block whose centre is inside this ring (60 px) is taken when you press
  noFill();
  stroke(pressing ? color(230, 60, 50) : color(200, 90, 80), 150);
  strokeWeight(2);
  ellipse(0, 0, 120, 120);
  noStroke();
  float angle = 2 * acos((float) Math.max(-1, Math.min(1, q[0])));
  float norm = (float) Math.sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (norm > 1e-6) {
    rotate(angle, (float) (q[1] / norm), (float) (q[2] / norm), (float) (q[3] / norm));
  }
  fill(pressing ? color(230, 60, 50) : color(200, 90, 80));
  sphere(9);
  stroke(60);
  strokeWeight(3);
  line(0, 0, 0, 0, -40, 0);
  popMatrix();
  popMatrix();
  fill(30);
  textSize(14);
  text((haptics.hasGrip() ? "Hold the VerseGrip's button" : "Press the mouse") + " near a block to grab it.   T: telemetry",
      12, 22);
  text(haptics.telemetryLine(), 12, 42);
  haptics.drawStatus();
}

int nearest(ModelSnapshot s, float within) {
  int best = -1;
  double bestD = within;
  for (int i = 0; i < blocks; i++) {
    int m = mdl.getMatIndex("block" + i);
    double d = Math.sqrt(sq((float) (s.x(m) - s.x(avatar))) + sq((float) (s.y(m) - s.y(avatar)))
        + sq((float) (s.z(m) - s.z(avatar))));
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

void keyPressed() {
  if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
