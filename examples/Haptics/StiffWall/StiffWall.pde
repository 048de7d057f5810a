/*
 * StiffWall: push the handle into a stiff wall. A wall stiffer than the device can render
 * (about 2 b / T: its own damping b over the loop's period T) buzzes or bounces, because the
 * sampled loop gives the hand a little more energy than it took at every touch. Press P to
 * switch on the passivity controller: it watches that energy and dissipates exactly what the
 * wall created, and the same wall settles. Press V for a virtual coupling instead: the hand
 * then feels a spring-damper that the device can render, tied to a proxy that touches the wall
 * (switched while the loop runs; the proxy starts at the handle, so there is no jolt).
 *
 * The plot at the bottom is the passivity observer: in red the energy the wall gave back to
 * the hand, in blue what the controller dissipated, per frame, and the totals. Energy that
 * comes back to the hand beyond what it put in is the buzz you feel.
 *
 * With no Haply plugged in, the sketch runs the board emulator and the mouse is your hand.
 * The red dot is the avatar, the ring the handle, the blue line the handle's recent path. The 2DIY's motors give at most about 1.5 N,
 * so a deep push only feels the torque limit: the buzz is at the face of the wall.
 *
 * S switches to the recommended stiff-wall setting (loop.useStiffContacts()): the force is bounded
 * by the energy your hand put in, so the wall never gives back more than it took and does not buzz.
 * On the 2DIY it comes with the count reserve (R switches it): a wall with friction is then never
 * lost to the encoders' one-count flicker, felt at about 500 N/m. Without the reserve the wall is
 * felt stiffer (about 1000 N/m, at most 1600 N/m) but can be lost (no force at all) in slow
 * presses, with a loose hold and on a device without friction (docs/haptics-stability.md,
 * "Stiff contacts" and "The adversarial suite"). P (the passivity controller) is on at start.
 *
 * Controls: S stiff-contact setting on/off, R count reserve on/off, P passivity controller on/off, V virtual coupling
 * on/off, 1-4 wall stiffness, T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel; the wall's stiffness is given in N/m at the handle.
 */

import tactus.*;
import tactus.haptics.*;
import tactus.haptics.passivity.*;

PhysicalModel mdl;
HapticSession haptics;
HapticLoop loop;

float forceGain = 1;                  // newtons per model force unit
float[] wallNm = {300, 1000, 3000, 10000};   // wall stiffness at the handle, N/m
int wallChoice = 2;
float wallX;                          // the wall's face, pixels: the wall fills x < wallX
boolean stiff = false;                // the energy bound for stiff walls (S), not yet the default
boolean reserve = true;               // its count reserve (R; on with S's setting): never lost to flicker, felt softer
boolean controller = true;
boolean coupling = false;
double deviceDamping = 0.5;           // N s/m: the emulator's handle; measure your device's
int history = 300;                    // frames in the plot
float[] toHand = new float[history];  // mJ per frame
float[] damped = new float[history];
int head = 0;
double lastOut, lastDissipated;
double[] force = new double[2];
double[] handle = new double[3];
int avatar;
int trail = 90;                       // frames of the handle's path drawn behind it
float[] trailX = new float[trail];
float[] trailY = new float[trail];
int trailHead = 0;

void setup() {
  size(800, 600);
  frameRate(60);
  haptics = HapticSession.open(this);   // a Haply if one is plugged in, else the emulator
  double[] ws = new double[4];
  haptics.workspace(ws);
  Vect3D home = haptics.home();
  // the wall's face near the left of the workspace: the idle tour (0.15..0.85 of it) grazes it
  wallX = (float) Math.min(home.x - 20, ws[0] + 0.17 * (ws[1] - ws[0]));
  startLoop();
}

/** A model with the avatar and the wall, and a loop with the chosen options. */
void startLoop() {
  Vect3D start = mdl == null ? haptics.home() : mdl.getMatPosition("avatar");
  start.x = Math.max(start.x, wallX + 10);
  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.addHapticInput3D("avatar", start, 1);   // no smoothing: the wall is as stiff as its K says
  // stiffness per pixel in model force units: K [N/m] / (pixels per metre x newtons per unit)
  double k = wallNm[wallChoice] / (haptics.positionGain() * forceGain);
  mdl.addPlaneContact("wall", 0, k, 0, 0, wallX, "avatar");
  mdl.init();
  avatar = mdl.getMatIndex("avatar");
  loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(forceGain);
  loop.setExchangeDelay(1);             // the board applies a torque about a tick after the reading
  if (coupling) {
    loop.setVirtualCoupling(VirtualCoupling.forDevice(deviceDamping, 1.0 / loop.rate(), 1));
  }
  loop.setPassivityControl(controller);
  if (stiff) {
    // passive, no buzz, also when the wall changes under the handle; with the count reserve unless R took it off
    loop.useStiffContacts();
  }
  loop.setEnergyBoundCountReserve(reserve ? HapticLoop.ROBUST_COUNT_RESERVE : 0);
  loop.start();
  lastOut = 0;
  lastDissipated = 0;
}

void draw() {
  background(245);
  ModelSnapshot s = mdl.getSnapshot();
  PassivityObserver energy = loop.passivity();

  // the wall
  noStroke();
  fill(90, 100, 120);
  rect(0, 60, wallX, height - 200);
  double[] ws = new double[4];
  haptics.workspace(ws);
  noFill();
  stroke(200);
  rect((float) ws[0], (float) ws[2], (float) (ws[1] - ws[0]), (float) (ws[3] - ws[2]));

  // the avatar (red) and, with a coupling, the handle it is tied to (ring)
  float ax = (float) s.x(avatar);
  float ay = (float) s.y(avatar);
  loop.devicePosition(handle);
  double[] model = new double[2];
  loop.deviceToModel(handle[0], handle[1], model);
  // the handle's path over the last frames: where the hand went, and whether it bounced off the wall
  trailX[trailHead] = (float) model[0];
  trailY[trailHead] = (float) model[1];
  trailHead = (trailHead + 1) % trail;
  noFill();
  strokeWeight(2);
  for (int i = 1; i < trail; i++) {
    int a = (trailHead + i - 1) % trail;
    int b = (trailHead + i) % trail;
    if (trailX[a] != 0 && trailX[b] != 0) {
      stroke(120, 160, 220, 255 * i / trail);
      line(trailX[a], trailY[a], trailX[b], trailY[b]);
    }
  }
  strokeWeight(1);
  stroke(60);
  line(ax, ay, (float) model[0], (float) model[1]);
  noFill();
  ellipse((float) model[0], (float) model[1], 22, 22);   // the handle
  noStroke();
  fill(220, 50, 40);
  ellipse(ax, ay, 16, 16);
  haptics.forceInModel(force);
  stroke(240, 150, 30);
  strokeWeight(3);
  line(ax, ay, ax + 20 * (float) force[0], ay + 20 * (float) force[1]);
  strokeWeight(1);

  // the passivity observer, per frame
  double out = energy.energyOut();
  double diss = energy.dissipated();
  toHand[head] = (float) (1000 * (out - lastOut));
  damped[head] = (float) (1000 * (diss - lastDissipated));
  lastOut = out;
  lastDissipated = diss;
  head = (head + 1) % history;
  drawPlot(20, height - 130, width - 40, 110);

  fill(30);
  textSize(14);
  text("Push into the wall.   S: energy bound " + (stiff ? "ON" : "off") + "   R: count reserve " + (reserve ? "ON" : "off")
    + "   P: controller " + (controller ? "ON" : "off") + "   V: coupling " + (coupling ? "ON" : "off")
    + "   1-4: wall " + (int) wallNm[wallChoice] + " N/m   T: telemetry", 12, 22);
  text(String.format("energy in %.2f mJ, back to the hand %.2f mJ, net %.2f mJ, dissipated by the controller %.2f mJ, active %.1f %% of ticks",
    1000 * energy.energyIn(), 1000 * out, 1000 * energy.netEnergy(), 1000 * diss, 100 * energy.activeShare()), 12, 42);
  haptics.drawStatus();
}

/** Per-frame energy back to the hand (red) and dissipated by the controller (blue), in millijoules. */
void drawPlot(float x, float y, float w, float h) {
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
  text(String.format("energy per frame, top %.2f mJ: red back to the hand, blue dissipated by the controller", top), x + 4, y + 14);
}

void keyPressed() {
  if (key == 's' || key == 'S') {
    stiff = !stiff;
    if (stiff) {
      loop.useStiffContacts();   // at once, while the loop runs
      loop.setEnergyBoundCountReserve(reserve ? HapticLoop.ROBUST_COUNT_RESERVE : 0);   // R's choice
      controller = false;
      coupling = false;
    } else {
      loop.setEnergyBound(0);
      controller = true;                       // back to the start's setting
      loop.setPassivityControl(true);
    }
  } else if (key == 'r' || key == 'R') {
    reserve = !reserve;
    loop.setEnergyBoundCountReserve(reserve ? HapticLoop.ROBUST_COUNT_RESERVE : 0);   // at once, while the loop runs
  } else if (key == 'p' || key == 'P') {
    controller = !controller;
    loop.setPassivityControl(controller);   // switches at once, while the loop runs
  } else if (key == 'v' || key == 'V') {
    coupling = !coupling;
    // switches at the loop's next tick, while it runs: the proxy starts at the handle (no jolt)
    loop.setVirtualCoupling(coupling ? VirtualCoupling.forDevice(deviceDamping, 1.0 / loop.rate(), 1) : null);
  } else if (key >= '1' && key <= '4') {
    wallChoice = key - '1';
    startLoop();
  } else if (key == 't' || key == 'T') {
    loop.printTelemetry();
    println(loop.passivity());
  }
}
