"""How a robot floats and moves through the scene's water: buoyancy and drag on its hull
(`buoyancy`, `drag`) and the depth it starts at (`depth`). No RoBIOS calls: a program feels the
water only through its robot's motion."""
