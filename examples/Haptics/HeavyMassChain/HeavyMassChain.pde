/*
 * HeavyMassChain: drag a chain of heavy masses with the Haply and feel their inertia.
 * The avatar (red) pulls ten masses through loose springs: starting, stopping or turning
 * takes effort, and the chain keeps swinging after you stop. Press M to make the masses
 * ten times lighter and feel the difference.
 *
 * With no Haply plugged in, the sketch runs the board emulator and the mouse is your hand
 * (the avatar lags behind the mouse by as much as the chain pulls on it).
 *
 * Controls: M heavy / light masses, R straighten the chain, T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, parameters per step of the 1 kHz haptic loop.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession haptics;

int nMasses = 10;
float heavy = 50;        // mass of each chain element
float light = 5;
boolean isHeavy = true;
float spacing = 30;      // rest length of each spring, pixels
float stiffness = 0.002; // loose springs: a slow swing (about 1 Hz with the heavy masses)
float damping = 0.05;
int[] index = new int[nMasses + 1];   // mass indices in the model (0: the avatar)
double[] force = new double[2];

void setup() {
  size(800, 600);
  frameRate(60);
  // A Haply if one is plugged in, otherwise the emulator with the mouse as the hand.
  haptics = HapticSession.open(this);
  buildChain();
  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(10);   // newtons per model force unit: about 1 N for a 50-pixel stretch
  loop.start();            // 1 kHz; the haptic thread steps the model
}

void buildChain() {
  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0002);
  Vect3D home = haptics.home();   // the avatar starts where the handle is
  mdl.addHapticInput3D("avatar", home, 10);
  mdl.createMatSubset("chain");
  for (int i = 0; i < nMasses; i++) {
    mdl.addMass3D("m" + i, heavy, new Vect3D(home.x + spacing * (i + 1), home.y, 0), new Vect3D());
    mdl.addMatToSubset("m" + i, "chain");
  }
  mdl.addSpringDamper3D("grip", spacing, stiffness, damping, "avatar", "m0");
  for (int i = 0; i + 1 < nMasses; i++) {
    mdl.addSpringDamper3D("k" + i, spacing, stiffness, damping, "m" + i, "m" + (i + 1));
  }
  mdl.init();
  index[0] = mdl.getMatIndex("avatar");
  for (int i = 0; i < nMasses; i++) {
    index[i + 1] = mdl.getMatIndex("m" + i);
  }
}

void draw() {
  background(24, 28, 36);
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the haptic thread

  // what the device can reach
  double[] ws = new double[4];
  haptics.workspace(ws);
  noFill();
  stroke(60, 70, 90);
  rect((float) ws[0], (float) ws[2], (float) (ws[1] - ws[0]), (float) (ws[3] - ws[2]));

  stroke(120, 200, 140);
  strokeWeight(2);
  for (int i = 0; i < nMasses; i++) {
    line((float) s.x(index[i]), (float) s.y(index[i]), (float) s.x(index[i + 1]), (float) s.y(index[i + 1]));
  }
  noStroke();
  float size = isHeavy ? 22 : 12;
  fill(90, 200, 120);
  for (int i = 1; i <= nMasses; i++) {
    ellipse((float) s.x(index[i]), (float) s.y(index[i]), size, size);
  }

  // the avatar and the force you feel (40 pixels per newton)
  float ax = (float) s.x(index[0]);
  float ay = (float) s.y(index[0]);
  haptics.forceInModel(force);
  stroke(255, 210, 80);
  strokeWeight(3);
  line(ax, ay, ax + 40 * (float) force[0], ay + 40 * (float) force[1]);
  noStroke();
  fill(230, 60, 50);
  ellipse(ax, ay, 18, 18);

  fill(230);
  textSize(14);
  text("Drag the chain and feel its inertia.   M: " + (isHeavy ? "light" : "heavy") + " masses   R: reset   T: print telemetry",
    12, 22);
  text(String.format("force %.2f N   masses %.0f each   %s", Math.hypot(force[0], force[1]), isHeavy ? heavy : light,
    haptics.telemetryLine()), 12, 42);
  haptics.drawStatus();   // which board, or that the mouse is your hand
}

void keyPressed() {
  if (key == 'm' || key == 'M') {
    isHeavy = !isHeavy;
    mdl.changeMassParamOfSubset(isHeavy ? heavy : light, "chain");
  } else if (key == 'r' || key == 'R') {
    Vect3D a = mdl.getMatPosition("avatar");
    for (int i = 0; i < nMasses; i++) {
      mdl.setMatPosition("m" + i, new Vect3D(a.x + spacing * (i + 1), a.y, 0));
      mdl.setMatVelocity("m" + i, new Vect3D());
    }
  } else if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
