/*
 * Bowl3D: your hand is inside a round bowl with eight marbles. Feel the bowl's wall in every
 * direction, and stir the marbles, which bounce off the wall, off each other and off you.
 *
 * Device: an Inverse3 through the Inverse Service, else a 2DIY board, else the emulated
 * Inverse3 with the mouse as your hand.
 * Controls: T print the loop's telemetry.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, parameters per step of the 1 kHz haptic loop.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession3D haptics;
int marbles = 8;
float radius = 180;
int avatar;

void setup() {
  size(800, 600, P3D);
  frameRate(60);
  haptics = HapticSession3D.open(this);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.0003);
  mdl.addGround3D("centre", new Vect3D(width / 2, height / 2, 0));
  mdl.addHapticInput3D("avatar", haptics.home(), 10);
  mdl.addBubble3D("wall", radius - 10, 0.05, 0.005, "avatar", "centre");   // the hand stays inside
  for (int i = 0; i < marbles; i++) {
    float a = TWO_PI * i / marbles;
    mdl.addMass3D("marble" + i, 5, new Vect3D(width / 2 + 90 * cos(a), height / 2 + 90 * sin(a), 40 * sin(2 * a)),
        new Vect3D());
    mdl.addBubble3D("wall" + i, radius - 16, 0.05, 0.005, "marble" + i, "centre");
    mdl.addContact3D("hand" + i, 26, 0.05, 0.005, "avatar", "marble" + i);
    for (int j = 0; j < i; j++) {
      mdl.addContact3D("pair" + i + "_" + j, 32, 0.05, 0.005, "marble" + i, "marble" + j);
    }
  }
  mdl.init();
  avatar = mdl.getMatIndex("avatar");

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(2);
  loop.start();
}

void draw() {
  background(250);
  lights();
  ModelSnapshot s = mdl.getSnapshot();
  pushMatrix();
  translate(width / 2, height / 2, 0);
  rotateX(-0.5);
  rotateY(frameCount * 0.002);
  noFill();
  stroke(200);
  sphereDetail(16);
  sphere(radius);
  translate(-width / 2, -height / 2, 0);
  noStroke();
  sphereDetail(12);
  for (int i = 0; i < s.getNumberOfMats(); i++) {
    if (s.getMatType(i) == matModuleType.Ground3D) {
      continue;
    }
    pushMatrix();
    translate((float) s.x(i), (float) s.y(i), (float) s.z(i));
    fill(i == avatar ? color(220, 50, 40) : color(40, 120, 200));
    sphere(i == avatar ? 10 : 16);
    popMatrix();
  }
  popMatrix();
  fill(30);
  textSize(14);
  text("Feel the bowl, stir the marbles.   T: telemetry", 12, 22);
  text(haptics.telemetryLine(), 12, 42);
  haptics.drawStatus();
}

void keyPressed() {
  if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
