"""The domain formulas: the load cycle, the motion and the mechanism, the gearbox, couplings, motor,
stiffness, hysteresis, transmission and positioning accuracy, each formula defined once as a
:class:`calc.core.formula.Formula` in the module of its topic."""
