/*
 * StiffWall3D: push the handle into the corner of a stiff box, a side wall on the left and a back wall
 * away from you. A wall stiffer than the device can render (about 2 b / T: its own damping b over
 * the loop's period T) buzzes or bounces, because the sampled loop gives the hand a little more
 * energy than it took at every touch. Press P to switch on the passivity controller: it watches that
 * energy and dissipates exactly what the walls created, and the same walls settle. Press V for a
 * virtual coupling instead (switched while the loop runs): the hand then feels a soft spring to the
 * avatar (the ring and the ball part), safe whatever the wall, but much softer than the wall.
 *
 * The plot at the bottom is the passivity observer: in red the energy the walls gave back to the
 * hand, in blue what the controller dissipated, per frame, and the totals (energy in and out, net,
 * the share of ticks in which the controller acted). Energy that comes back to the hand beyond what
 * it put in is the buzz you feel.
 *
 * Device: an Inverse3 through the Inverse Service, else a 2DIY board (then only the side wall can be
 * reached: z is fixed), else the emulated Inverse3 with the mouse as your hand (x and y follow the
 * mouse, the depth swings slowly on its own, so the back wall is touched now and then). The emulated
 * Inverse3 runs the generic 3-DoF device plant (0.2 kg and 0.5 N s/m per axis, Coulomb friction),
 * the one measured in docs/haptics-stability.md, "In 3-D and at audio rate".
 * The red ball is the avatar, the ring the handle; the walls turn red where they are touched.
 *
 * S switches to the recommended stiff-wall setting (loop.useStiffContacts()): the force is bounded
 * by the energy your hand put in, so the wall never gives back more than it took and does not buzz.
 * On an Inverse3 it is felt as up to 3300 N/m and passes every case of the adversarial suite on the
 * emulated 3-DoF plant (docs/haptics-stability.md, "On the 3-DoF plant"); on a 2DIY it comes with
 * the count reserve, never gives the hand energy either and is felt at about 500 N/m ("The adversarial
 * suite"). P (the passivity controller) is on at start.
 *
 * Controls: S stiff-contact setting on/off, P passivity controller on/off, V virtual coupling on/off, 1-4 wall stiffness,
 *           T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel; the walls' stiffness is given in N/m at the handle.
 */

import tactus.*;
import tactus.haptics.*;
import tactus.haptics.emulator.*;
import tactus.haptics.passivity.*;

PhysicalModel mdl;
HapticSession3D haptics;
HapticLoop loop;

float forceGain = 1;                          // newtons per model force unit
float[] wallNm = {300, 1000, 3000, 10000};    // wall stiffness at the handle, N/m
int wallChoice = 2;
boolean stiff = false;                // the recommended stiff-wall setting (S): loop.useStiffContacts()
boolean controller = true;
boolean coupling = false;
double[] lo = new double[3];                  // the comfortable workspace, pixels
double[] hi = new double[3];
float sideX;                                  // the side wall fills x < sideX
float backZ;                                  // the back wall fills z < backZ (away from you)
int history = 300;                            // frames in the plot
float[] toHand = new float[history];          // mJ per frame
float[] damped = new float[history];
int head = 0;
double lastOut, lastDissipated;
double[] handle = new double[3];
double[] handleModel = new double[3];
double[] force = new double[3];
int avatar;

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  haptics = HapticSession3D.open(this);
  if (haptics.isEmulated()) {
    haptics.emulator().device().setPlant(PlantParameters.cartesian3Dof());   // a device with dynamics
  }
  haptics.workspace(lo, hi);
  // the walls cut a fifth of the workspace off on the left and at the back: the idle tour and the mouse's
  // depth swing reach into both
  sideX = (float) (lo[0] + 0.2 * (hi[0] - lo[0]));
  backZ = (float) (lo[2] + 0.25 * (hi[2] - lo[2]));
  startLoop();
}

/** A model with the avatar and the two walls of the chosen stiffness, and a loop with the controller as chosen. */
void startLoop() {
  Vect3D start = mdl == null ? haptics.home() : mdl.getMatPosition("avatar");
  start.x = Math.max(start.x, sideX + 10);
  start.z = Math.max(start.z, backZ + 10);
  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.addHapticInput3D("avatar", start, 1);   // no smoothing: the walls are as stiff as their K says
  // stiffness per pixel in model force units: K [N/m] / (pixels per metre x newtons per unit)
  double k = wallNm[wallChoice] / (haptics.mapping().scale() * forceGain);
  mdl.addPlaneContact("side", 0, k, 0, 0, sideX, "avatar");
  mdl.addPlaneContact("back", 0, k, 0, 2, backZ, "avatar");
  mdl.init();
  avatar = mdl.getMatIndex("avatar");
  loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(forceGain);
  // an Inverse3-class handle (0.2 kg) is ten times heavier than a 2DIY's: let the controller damp in proportion,
  // but below m / (T (W + 1/2)) = 44 N s/m, where its own damper, delayed by answers up to W = 4 ticks late, would
  // shake the handle (docs/haptics-stability.md, "In 3-D and at audio rate")
  loop.setPassivityDampingLimit(40);
  loop.setPassivityControl(controller);
  if (coupling) {
    loop.setVirtualCoupling(deviceCoupling());
  }
  if (stiff) {
    // bounds the force by the energy the hand put in: passive and without buzz, the walls felt as at most
    // 3300 N/m on an Inverse3, 1600 N/m on a 2DIY (measured on the emulated plants)
    loop.useStiffContacts();
  }
  loop.start();
  lastOut = 0;
  lastDissipated = 0;
}

void draw() {
  background(245);
  lights();
  ModelSnapshot s = mdl.getSnapshot();
  float ax = (float) s.x(avatar);
  float ay = (float) s.y(avatar);
  float az = (float) s.z(avatar);
  loop.devicePosition(handle);
  haptics.mapping().toModel(handle, handleModel);

  pushMatrix();
  translate(width / 2, height / 2, -120);   // back a little, so that the whole box is in view
  rotateX(-0.3);
  rotateY(0.3);
  translate(-width / 2, -height / 2, 0);
  drawWorkspace();
  drawWalls(ax < sideX, az < backZ);
  // the avatar (red) and the handle (ring), joined by a line when they part
  noStroke();
  fill(220, 50, 40);
  pushMatrix();
  translate(ax, ay, az);
  sphereDetail(12);
  sphere(9);
  popMatrix();
  if (!Double.isNaN(handleModel[0])) {
    stroke(60);
    line(ax, ay, az, (float) handleModel[0], (float) handleModel[1], (float) handleModel[2]);
    noFill();
    pushMatrix();
    translate((float) handleModel[0], (float) handleModel[1], (float) handleModel[2]);
    ellipse(0, 0, 24, 24);
    popMatrix();
  }
  haptics.forceInModel(force);
  stroke(240, 150, 30);
  strokeWeight(3);
  line(ax, ay, az, ax + 20 * (float) force[0], ay + 20 * (float) force[1], az + 20 * (float) force[2]);
  strokeWeight(1);
  popMatrix();

  // the passivity observer, per frame, drawn flat over the scene
  hint(DISABLE_DEPTH_TEST);
  PassivityObserver energy = loop.passivity();
  double out = energy.energyOut();
  double diss = energy.dissipated();
  toHand[head] = (float) (1000 * (out - lastOut));
  damped[head] = (float) (1000 * (diss - lastDissipated));
  lastOut = out;
  lastDissipated = diss;
  head = (head + 1) % history;
  drawPlot(20, height - 140, width - 40, 110);
  fill(30);
  textSize(14);
  text("Push into the corner.   S: stiff contacts " + (stiff ? "ON" : "off") + "   P: controller " + (controller ? "ON" : "off")
    + "   V: coupling " + (coupling ? "ON" : "off") + "   1-4: walls "
    + (int) wallNm[wallChoice] + " N/m   T: telemetry", 12, 22);
  text(String.format("energy in %.2f mJ, back to the hand %.2f mJ, net %.2f mJ", 1000 * energy.energyIn(),
    1000 * out, 1000 * energy.netEnergy()), 12, 42);
  text(String.format("dissipated by the controller %.2f mJ, active in %.1f %% of %d ticks", 1000 * diss,
    100 * energy.activeShare(), energy.ticks()), 12, 60);
  haptics.drawStatus();
  hint(ENABLE_DEPTH_TEST);
}

/** The comfortable workspace as a wire box. */
void drawWorkspace() {
  noFill();
  stroke(200);
  pushMatrix();
  translate((float) (0.5 * (lo[0] + hi[0])), (float) (0.5 * (lo[1] + hi[1])), (float) (0.5 * (lo[2] + hi[2])));
  box((float) (hi[0] - lo[0]), (float) (hi[1] - lo[1]), (float) (hi[2] - lo[2]));
  popMatrix();
}

/** The side wall (x = sideX) and the back wall (z = backZ) as translucent faces, red while touched. */
void drawWalls(boolean sideTouched, boolean backTouched) {
  float y0 = (float) lo[1];
  float y1 = (float) hi[1];
  stroke(90, 100, 120);
  fill(sideTouched ? color(220, 80, 70, 140) : color(90, 100, 120, 70));
  beginShape(QUADS);
  vertex(sideX, y0, backZ);
  vertex(sideX, y1, backZ);
  vertex(sideX, y1, (float) hi[2]);
  vertex(sideX, y0, (float) hi[2]);
  endShape();
  fill(backTouched ? color(220, 80, 70, 140) : color(110, 120, 140, 60));
  beginShape(QUADS);
  vertex(sideX, y0, backZ);
  vertex((float) hi[0], y0, backZ);
  vertex((float) hi[0], y1, backZ);
  vertex(sideX, y1, backZ);
  endShape();
}

/** Per-frame energy back to the hand (red) and dissipated by the controller (blue), in millijoules. */
void drawPlot(float x, float y, float w, float h) {
  noStroke();
  fill(255, 230);
  rect(x, y, w, h);
  noFill();
  stroke(200);
  rect(x, y, w, h);
  float top = 0.05;   // mJ per frame at the top of the plot
  for (int i = 0; i < history; i++) {
    top = max(top, max(toHand[i], damped[i]));
  }
  for (int i = 0; i < history; i++) {
    int j = (head + i) % history;
    float px = x + w * i / (history - 1);
    stroke(220, 40, 40);
    line(px, y + h, px, y + h - h * toHand[j] / top);
    stroke(40, 90, 220);
    point(px, y + h - h * damped[j] / top);
  }
  fill(80);
  textSize(11);
  text(String.format("energy per frame, top %.2f mJ: red back to the hand, blue dissipated by the controller", top),
    x + 4, y + 14);
}

/**
 * The coupling that is passive on the device by construction: the generic 3-DoF plant's damping (0.5 N s/m per
 * axis), the loop's period, and one tick of delay (the service's answers are sometimes a tick late).
 */
VirtualCoupling deviceCoupling() {
  return VirtualCoupling.forDevice(0.5, 1.0 / loop.rate(), 1);
}

void keyPressed() {
  if (key == 's' || key == 'S') {
    stiff = !stiff;
    if (stiff) {
      loop.useStiffContacts();   // at once, while the loop runs
      controller = false;
      coupling = false;
    } else {
      loop.setEnergyBound(0);
      controller = true;                       // back to the start's setting
      loop.setPassivityControl(true);
    }
  } else if (key == 'p' || key == 'P') {
    controller = !controller;
    loop.setPassivityControl(controller);   // switches at once, while the loop runs
  } else if (key == 'v' || key == 'V') {
    coupling = !coupling;
    loop.setVirtualCoupling(coupling ? deviceCoupling() : null);   // bumpless: the proxy starts at the handle
  } else if (key >= '1' && key <= '4') {
    wallChoice = key - '1';
    startLoop();
  } else if (key == 't' || key == 'T') {
    loop.printTelemetry();
    println(loop.passivity());
  }
}
