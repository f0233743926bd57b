"""Contact loads of a rigid valve train: spring and inertia forces, clearance, friction/load
iteration and loss of contact. Physics only: inputs are a Kinematics object and SI numbers."""
from camtrain.loads.bounce import Bounce, bounce_speed, loss_of_contact
from camtrain.loads.desmodromic import DesmodromicLoads, desmodromic_loads, handover_angles
from camtrain.loads.forces import contact_load, contact_mask, load_parts, spring_force, valve_force
from camtrain.loads.iteration import LoadSolution, iterate_load
from camtrain.loads.product import ContactLoad

__all__ = ["Bounce", "ContactLoad", "DesmodromicLoads", "LoadSolution", "bounce_speed", "contact_load",
           "contact_mask", "desmodromic_loads", "handover_angles", "iterate_load", "load_parts",
           "loss_of_contact", "spring_force", "valve_force"]
