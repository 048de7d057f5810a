/*
 * HapticsOnlyTemplate: start here for a haptic scene of your own.
 * Put your masses and interactions in buildModel(); the template opens the Haply (or the
 * emulator, with the mouse as your hand, when none is plugged in), runs the 1 kHz haptic
 * loop that steps your model, and draws every mass and interaction it finds.
 *
 * Controls: T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel (y down the window), parameters per step of the
 * haptic loop. The avatar, a HapticInput3D called "avatar", is your hand in the model.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession haptics;
int hapticRate = 1000;     // steps per second; 200 leaves five times more time per step
float forceGain = 1;       // newtons per model force unit: tune it to your model's forces
double[] force = new double[2];
int avatar;                // index of the avatar in the model

void setup() {
  size(800, 600);
  frameRate(60);
  // A Haply if one is plugged in, otherwise the emulator with the mouse as the hand.
  haptics = HapticSession.open(this);

  mdl = new PhysicalModel(hapticRate, 60, paramSystem.ALGO_UNITS);
  mdl.addHapticInput3D("avatar", haptics.home(), 10);   // starts where the handle is
  buildModel();
  mdl.init();
  avatar = mdl.getMatIndex("avatar");

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setRate(hapticRate);
  loop.setForceGain(forceGain);
  loop.start();   // the haptic thread now steps the model: no draw_physics() in draw()
}

/** YOUR MODEL GOES HERE. This one is a soft ball on a spring: push it with the avatar. */
void buildModel() {
  mdl.setFriction(0.0005);
  mdl.addGround3D("post", new Vect3D(width / 2, height / 2, 0));
  mdl.addMass3D("ball", 20, new Vect3D(width / 2, height / 2, 0), new Vect3D());
  // name, rest length, stiffness, damping, first mass, second mass
  mdl.addSpringDamper3D("spring", 0, 0.001, 0.02, "post", "ball");
  // the avatar touches the ball when their centres come closer than 20 pixels (the drawn radii)
  mdl.addContact3D("touch", 20, 0.05, 0.01, "avatar", "ball");
}

void draw() {
  background(250);
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the haptic thread

  double[] ws = new double[4];           // what the device can reach
  haptics.workspace(ws);
  noFill();
  stroke(220);
  rect((float) ws[0], (float) ws[2], (float) (ws[1] - ws[0]), (float) (ws[3] - ws[2]));

  stroke(120);
  strokeWeight(1.5);
  for (int l = 0; l < s.getNumberOfLinks(); l++) {
    int a = s.getLinkMat1Idx(l);
    int b = s.getLinkMat2Idx(l);
    if (a != b && s.getLinkType(l) != linkModuleType.Contact3D) {   // contacts are not drawn
      line((float) s.x(a), (float) s.y(a), (float) s.x(b), (float) s.y(b));
    }
  }
  noStroke();
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    matModuleType t = s.getMatType(i);
    float size = 24;
    if (t == matModuleType.HapticInput3D) {
      fill(220, 50, 40);
      size = 16;
    } else if (t == matModuleType.Ground3D) {
      fill(60, 160, 90);
      size = 10;
    } else {
      fill(40, 90, 200, 200);
    }
    ellipse((float) s.x(i), (float) s.y(i), size, size);
  }

  // the force you feel, 40 pixels per newton
  float ax = (float) s.x(avatar);
  float ay = (float) s.y(avatar);
  haptics.forceInModel(force);
  stroke(240, 150, 30);
  strokeWeight(3);
  line(ax, ay, ax + 40 * (float) force[0], ay + 40 * (float) force[1]);

  fill(30);
  textSize(14);
  text("Your model, at " + hapticRate + " Hz.   T: print telemetry", 12, 22);
  text(String.format("force %.2f N   %s", Math.hypot(force[0], force[1]), haptics.telemetryLine()), 12, 42);
  haptics.drawStatus();   // which board, or that the mouse is your hand
}

void keyPressed() {
  if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
